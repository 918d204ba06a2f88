package org.beziertracer.model;

/**
 * Where a Bézier patch came from: piece {@code piece} of the {@code pieceCount} Bézier pieces of
 * a free-form {@code surface} as read from a file. Writers put the original surface back when
 * every piece is still there unchanged; an edited patch loses its origin
 * ({@link BezierPatch#withPoint}). Compared by the surface's identity.
 */
public record PatchOrigin(FreeFormSurface surface, int piece, int pieceCount) {
    public PatchOrigin {
        if (surface == null || piece < 0 || piece >= pieceCount) {
            throw new IllegalArgumentException("piece " + piece + " of " + pieceCount + " is not a piece of a surface");
        }
    }
}
