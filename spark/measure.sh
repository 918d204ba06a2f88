#!/usr/bin/env bash
# Measures the Spark module (docs/spark.md, "Numbers"): a 16-tile frame through local[2] against
# `render --threads 2` of the same frame (wall and CPU seconds, runs alternated), then tiles a second
# on local-cluster with 1 and 2 executor JVMs. Run from the repository root after
# `./mvnw -q -f spark/pom.xml compile`. Timings are noisy on a shared machine: compare the ratios.
#
# Both commands are timed the same way: a fresh JVM from launch to the last file on disk (bash's time,
# CPU = user + system of the process and its children), the same class path (our classes as one jar), the
# same JVM options (Spark's JDK 17 list, which holds --add-modules jdk.incubator.vector) and the same kernel.
#   RUNS=3              alternated runs of each size
#   SIZES="640x480 …"   frame sizes; SPP=32 samples per pixel
#   KERNEL=auto|simd|scalar   -Dbeziertracer.kernel of both commands (default: unset, i.e. auto)
#   VARIANTS="spark"    Spark runs per round, in order: spark (the default: no web UI), ui (with --ui),
#                       cds (AppCDS: each command with an archive dumped from a tiny run of its own; the
#                       round then also times `render` with its archive)
#   CLUSTER=1           0 skips the local-cluster curve
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
spp=${SPP:-32}          # samples per pixel of the frames measured against render
sizes=${SIZES:-"640x480 1280x960"}  # frame sizes (a bigger frame amortises Spark's start-up)
variants=${VARIANTS:-spark}
cspp=${CLUSTER_SPP:-4}  # samples per pixel of the local-cluster turntable (4 frames of 320x240)
work=$(mktemp -d)
./mvnw -q -o -f spark/pom.xml dependency:build-classpath -Dmdep.includeScope=compile -Dmdep.outputFile="$work/cp" >/dev/null
# our classes as a jar: the same class path for both commands, and one AppCDS accepts (it refuses folders)
(cd spark/target/classes && jar cf "$work/app.jar" .)
cp="$work/app.jar:$(cat "$work/cp")"
opts=$(sed -n 's:.*<spark.jvm.options>\(.*\)</spark.jvm.options>.*:\1:p' spark/pom.xml)
[ -n "${KERNEL:-}" ] && opts="$opts -Dbeziertracer.kernel=$KERNEL"
# bash's `time` (it times shell functions): wall, user and system seconds of the command and its children
timed() { local TIMEFORMAT="%R %U %S"; { time "$@" >"$work/spark.out" 2>/dev/null; } 2>"$work/time"; cat "$work/time"; }
render() { java $opts "$@" -cp "$cp" org.beziertracer.Main render "$work/frame.json" -o "$work/render.png" --threads 2 -q; }
spark() { rm -rf "$work/out"; java $opts "$@" -cp "$cp" org.beziertracer.spark.SparkRender "$work/frame.json" \
    "$work/out" --tiles 16 --master 'local[2]' ${SPARK_ARGS:-}; }
cpu() { echo "$2 + $3" | bc; }
if [[ " $variants " == *" cds "* ]]; then # one archive per command, dumped from a 32x16 frame
  echo '{"job": 1, "scene": "teapot", "settings": {"width": 32, "height": 16, "spp": 1}, "output": "f.png"}' \
      > "$work/frame.json"
  render -XX:ArchiveClassesAtExit="$work/render.jsa" >/dev/null 2>&1
  spark -XX:ArchiveClassesAtExit="$work/spark.jsa" >/dev/null 2>&1
  [ -s "$work/render.jsa" ] && [ -s "$work/spark.jsa" ] || { echo "measure.sh: no AppCDS archive" >&2; exit 1; }
fi
echo "load $(cut -d' ' -f1-3 /proc/loadavg); kernel ${KERNEL:-auto}; variants: $variants"
echo "size run command wall cpu ratio-to-render(cpu wall) load (seconds; CPU = user + system)"
for size in $sizes; do
  w=${size%x*}; h=${size#*x}
  cat > "$work/frame.json" <<JOB
{"job": 1, "scene": "teapot", "settings": {"width": $w, "height": $h, "spp": $spp, "sampler": "jittered"},
 "output": "frame.png"}
JOB
  for k in $(seq "$runs"); do
    read -r rw ru rs < <(timed render)
    rc=$(cpu x "$ru" "$rs")
    echo "$size $k render $rw $rc - $(cut -d' ' -f1 /proc/loadavg)"
    for v in $variants; do
      case $v in
        spark) read -r sw su ss < <(timed spark) ;;
        ui) read -r sw su ss < <(SPARK_ARGS=--ui timed spark) ;;
        cds) read -r cw cu cs < <(timed render -XX:SharedArchiveFile="$work/render.jsa")
             echo "$size $k render-cds $cw $(cpu x "$cu" "$cs") - $(cut -d' ' -f1 /proc/loadavg)"
             read -r sw su ss < <(timed spark -XX:SharedArchiveFile="$work/spark.jsa") ;;
        *) echo "unknown variant $v" >&2; exit 2 ;;
      esac
      sc=$(cpu x "$su" "$ss")
      echo "$size $k $v $sw $sc $(echo "scale=2; $sc / $rc" | bc) $(echo "scale=2; $sw / $rw" | bc)" \
          "$(cut -d' ' -f1 /proc/loadavg)"
      grep "tiles rendered\|^executor" "$work/spark.out" | sed 's/^/  /'
    done
  done
done
if [ "${CLUSTER:-1}" = 1 ]; then
  # local-cluster: executors through Spark's launcher (an empty $SPARK_HOME/jars; classes from extraClassPath)
  mkdir -p "$work/spark-home/jars"
  cat > "$work/frames.json" <<JOB
{"job": 1, "scene": "teapot", "settings": {"width": 320, "height": 240, "spp": $cspp, "sampler": "jittered"},
 "camera": {"turntable": {"frames": 4}}, "output": "t-#.png"}
JOB
  for n in 1 2; do
    rm -rf "$work/out"
    SPARK_HOME="$work/spark-home" SPARK_SCALA_VERSION=2.13 SPARK_LOCAL_IP=127.0.0.1 java $opts \
        -Dspark.executor.extraClassPath="$cp" -Dspark.executor.memory=512m -cp "$cp" \
        org.beziertracer.spark.SparkRender "$work/frames.json" "$work/out" --tiles 16 \
        --master "local-cluster[$n,1,1024]" | grep "tiles rendered" | sed "s/^/$n executor(s): /"
  done
fi
rm -rf "$work"
