package org.beziertracer.model;

import java.util.List;

import org.beziertracer.math.Vec3;

/**
 * How a job's camera moves from frame to frame (issue 37): a {@link Turntable} or a list of
 * {@link Keyframes}. {@link #at} is a pure function of the frame number and the base camera, computed
 * with {@link StrictMath} and plain products only, so every machine gets the same bits.
 *
 * <p>Frames are whole numbers; a job renders frames {@code 1..N} unless it says otherwise.
 */
public sealed interface CameraPath {

    /** The camera of {@code frame}; {@code base} is the scene's camera (or the fitted default). */
    CameraSpec at(int frame, CameraSpec base);

    /** The frames a job renders when it names none. */
    int firstFrame();

    int lastFrame();

    /**
     * The base camera turned about the line through {@code center} along {@code axis}: frame
     * {@code k} (1..frames) is turned by {@code degrees · (k − 1) / frames}, so with 360° the frame
     * after the last would be the first again. Eye and target turn as points, up as a direction;
     * the field of view stays. {@code center} null: the base camera's target. Rotation by Rodrigues'
     * formula, {@code v' = v cos θ + (a × v) sin θ + a (a · v)(1 − cos θ)}.
     */
    record Turntable(int frames, Vec3 axis, Vec3 center, double degrees) implements CameraPath {
        public Turntable {
            if (frames < 1) {
                throw new IllegalArgumentException("frames must be 1 or more, got " + frames);
            }
            if (axis == null || !axis.isFinite() || axis.length() == 0) {
                throw new IllegalArgumentException("the axis must be a finite nonzero vector");
            }
            if (center != null && !center.isFinite()) {
                throw new IllegalArgumentException("the center must be finite");
            }
            if (!Double.isFinite(degrees)) {
                throw new IllegalArgumentException("degrees must be finite, got " + degrees);
            }
        }

        /** Turn of frame {@code k}, in degrees. */
        public double angleDegrees(int k) {
            return degrees * (k - 1) / frames;
        }

        @Override
        public CameraSpec at(int frame, CameraSpec base) {
            double theta = StrictMath.toRadians(angleDegrees(frame));
            double c = StrictMath.cos(theta), s = StrictMath.sin(theta);
            Vec3 a = axis.normalize();
            Vec3 o = center != null ? center : base.target();
            Vec3 eye = o.add(turn(base.eye().sub(o), a, c, s));
            Vec3 target = o.add(turn(base.target().sub(o), a, c, s));
            return new CameraSpec(eye, target, turn(base.up(), a, c, s), base.fovDegrees(), base.orthoWidth());
        }

        private static Vec3 turn(Vec3 v, Vec3 a, double c, double s) {
            return v.scale(c).add(a.cross(v).scale(s)).add(a.scale(a.dot(v) * (1 - c)));
        }

        @Override public int firstFrame() { return 1; }

        @Override public int lastFrame() { return frames; }
    }

    /** One keyframe: the camera at {@code frame}, with a horizontal field of view {@code fov} in degrees. */
    record Keyframe(int frame, Vec3 eye, Vec3 target, Vec3 up, double fov) {
        public Keyframe {
            // the camera's own checks: finite, eye ≠ target, up not along the view, 0 < fov < 179
            new CameraSpec(eye, target, up, fov, 1);
            if (fov == 0) {
                throw new IllegalArgumentException("a keyframe's fov must be above 0 (no orthographic keyframes)");
            }
        }
    }

    /**
     * Cameras given at some frames (in increasing order) and interpolated linearly between them: eye,
     * target, up and fov each {@code a + (b − a)·s} with {@code s = (k − k0)/(k1 − k0)}. Before the
     * first keyframe the camera is the first one, after the last the last one. The base camera is not
     * used.
     */
    record Keyframes(List<Keyframe> keys) implements CameraPath {
        public Keyframes {
            keys = List.copyOf(keys);
            if (keys.isEmpty()) {
                throw new IllegalArgumentException("keyframes need at least one keyframe");
            }
            for (int i = 1; i < keys.size(); i++) {
                if (keys.get(i).frame() <= keys.get(i - 1).frame()) {
                    throw new IllegalArgumentException("keyframe frames must increase, got " + keys.get(i - 1).frame()
                            + " then " + keys.get(i).frame());
                }
            }
        }

        @Override
        public CameraSpec at(int frame, CameraSpec base) {
            Keyframe first = keys.get(0), last = keys.get(keys.size() - 1);
            if (frame <= first.frame()) {
                return spec(first);
            }
            if (frame >= last.frame()) {
                return spec(last);
            }
            int i = 1;
            while (keys.get(i).frame() < frame) {
                i++;
            }
            Keyframe k0 = keys.get(i - 1), k1 = keys.get(i);
            double s = (double) (frame - k0.frame()) / (k1.frame() - k0.frame());
            return CameraSpec.perspective(lerp(k0.eye(), k1.eye(), s), lerp(k0.target(), k1.target(), s),
                    lerp(k0.up(), k1.up(), s), k0.fov() + (k1.fov() - k0.fov()) * s);
        }

        private static CameraSpec spec(Keyframe k) {
            return CameraSpec.perspective(k.eye(), k.target(), k.up(), k.fov());
        }

        private static Vec3 lerp(Vec3 a, Vec3 b, double s) {
            return a.add(b.sub(a).scale(s));
        }

        @Override public int firstFrame() { return keys.get(0).frame(); }

        @Override public int lastFrame() { return keys.get(keys.size() - 1).frame(); }
    }
}
