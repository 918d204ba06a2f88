#!/usr/bin/env bash
# Measures the Spark module (docs/spark.md, "Numbers"): a 16-tile frame through local[2] against
# `render --threads 2` of the same frame (wall and CPU seconds, runs alternated), then tiles a second
# on local-cluster with 1 and 2 executor JVMs. Run from the repository root after
# `./mvnw -q -f spark/pom.xml compile`. Timings are noisy on a shared machine: compare the ratios.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
spp=${SPP:-32}          # samples per pixel of the frames measured against render
sizes=${SIZES:-"640x480 1280x960"}  # frame sizes (a bigger frame amortises Spark's start-up)
cspp=${CLUSTER_SPP:-4}  # samples per pixel of the local-cluster turntable (4 frames of 320x240)
work=$(mktemp -d)
./mvnw -q -o -f spark/pom.xml dependency:build-classpath -Dmdep.includeScope=compile -Dmdep.outputFile="$work/cp" >/dev/null
cp="$(pwd)/spark/target/classes:$(cat "$work/cp")"
opts=$(sed -n 's:.*<spark.jvm.options>\(.*\)</spark.jvm.options>.*:\1:p' spark/pom.xml)
timed() { /usr/bin/time -f "%e %U %S" -o "$work/time" "$@" >"$work/spark.out" 2>/dev/null; cat "$work/time"; }
echo "size run render-wall render-cpu spark-wall spark-cpu (seconds; CPU = user + system)"
for size in $sizes; do
  w=${size%x*}; h=${size#*x}
  cat > "$work/frame.json" <<JOB
{"job": 1, "scene": "teapot", "settings": {"width": $w, "height": $h, "spp": $spp, "sampler": "jittered"},
 "output": "frame.png"}
JOB
  for k in $(seq "$runs"); do
    read -r rw ru rs < <(timed java --add-modules jdk.incubator.vector -cp "$cp" org.beziertracer.Main render \
        "$work/frame.json" -o "$work/render.png" --threads 2 -q)
    rm -rf "$work/out"
    read -r sw su ss < <(timed java $opts -cp "$cp" org.beziertracer.spark.SparkRender "$work/frame.json" \
        "$work/out" --tiles 16 --master 'local[2]')
    echo "$size $k $rw $(echo "$ru + $rs" | bc) $sw $(echo "$su + $ss" | bc)"
    grep "tiles rendered\|^executor" "$work/spark.out" | sed 's/^/  /'
  done
done
# local-cluster: executors through Spark's launcher (an empty $SPARK_HOME/jars; classes from extraClassPath)
mkdir -p "$work/spark-home/jars"
cat > "$work/frames.json" <<JOB
{"job": 1, "scene": "teapot", "settings": {"width": 320, "height": 240, "spp": $cspp, "sampler": "jittered"},
 "camera": {"turntable": {"frames": 4}}, "output": "t-#.png"}
JOB
for n in 1 2; do
  rm -rf "$work/out"
  SPARK_HOME="$work/spark-home" SPARK_SCALA_VERSION=2.13 SPARK_LOCAL_IP=127.0.0.1 java $opts \
      -Dspark.executor.extraClassPath="$cp" -Dspark.executor.memory=512m -Dspark.ui.enabled=false -cp "$cp" \
      org.beziertracer.spark.SparkRender "$work/frames.json" "$work/out" --tiles 16 \
      --master "local-cluster[$n,1,1024]" | grep "tiles rendered" | sed "s/^/$n executor(s): /"
done
rm -rf "$work"
