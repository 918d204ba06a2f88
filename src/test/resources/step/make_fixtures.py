#!/usr/bin/env python3
"""Writes the STEP test fixtures of StepReaderTest, independently of the Java writer.

Run from this folder: python3 make_fixtures.py. Each fixture is a list of entity instances
numbered in order; the layout follows ISO 10303-21 (header, one DATA section) and the entities
ISO 10303-42 as AP214 uses them. Faces:
  sampler.stp  - a rational B-spline face (complex instance) trimmed by B-spline pcurves,
                 (last) the polynomial B-spline again, trimmed by a triangle of lines,
                 a polynomial B-spline face whose range is a rectangle of trimmed lines,
                 a plane with a square outer loop of lines and a circular hole,
                 a full cylinder (seam edges), a half cone, a sphere patch, a torus patch,
                 a plane bounded by a 3-D line there and back (skipped: no area)
  inches.stp   - a unit square plane face in inches
  assembly.stp - a part (one plane face) placed twice in an assembly and once by a mapped item
  analytic3d.stp - faces whose edges carry 3-D curves only (no pcurve): a whole cylinder between two
                 parallels with two window holes of two parallel arcs and two meridian lines, a sphere
                 patch between parallels and meridians with a hole of a tilted circle, a whole turn
                 of a surface of revolution (a B-spline profile) between two parallels, and two faces
                 left out with their reasons: an extrusion, a sphere cap bounded by one parallel only
"""
import math


class Step:
    def __init__(self):
        self.lines = []

    def add(self, text):
        self.lines.append(text)
        return "#%d" % len(self.lines)

    def write(self, path, schema="AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }"):
        with open(path, "w", newline="\n") as f:
            f.write("ISO-10303-21;\nHEADER;\n")
            f.write("/* written by make_fixtures.py */\n")
            f.write("FILE_DESCRIPTION(('STEP fixture'),'2;1');\n")
            f.write("FILE_NAME('%s','2026-12-05T00:00:00',('test'),('it''s a test'),'python','python','');\n" % path)
            f.write("FILE_SCHEMA(('%s'));\nENDSEC;\nDATA;\n" % schema)
            for k, t in enumerate(self.lines):
                f.write("#%d=%s;\n" % (k + 1, t))
            f.write("ENDSEC;\nEND-ISO-10303-21;\n")


def r(v):
    s = repr(float(v))
    return s.upper() if "e" in s else s


def pt(s, *c):
    return s.add("CARTESIAN_POINT('',(%s))" % ",".join(r(x) for x in c))


def dirn(s, *c):
    return s.add("DIRECTION('',(%s))" % ",".join(r(x) for x in c))


def axis3(s, o, z, x):
    return s.add("AXIS2_PLACEMENT_3D('',%s,%s,%s)" % (pt(s, *o), dirn(s, *z), dirn(s, *x)))


def units(s, inch=False):
    mm = s.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))")
    length = mm
    if inch:
        f = s.add("LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),%s)" % mm)
        length = s.add("(CONVERSION_BASED_UNIT('INCH',%s)LENGTH_UNIT()NAMED_UNIT(%s))"
                       % (f, s.add("DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.)")))
    rad = s.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))")
    sr = s.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())")
    unc = s.add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),%s,'distance_accuracy_value','')" % length)
    return s.add("(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((%s))"
                 "GLOBAL_UNIT_ASSIGNED_CONTEXT((%s,%s,%s))REPRESENTATION_CONTEXT('',''))" % (unc, length, rad, sr))


def ctx2d(s):
    return s.add("(GEOMETRIC_REPRESENTATION_CONTEXT(2)PARAMETRIC_REPRESENTATION_CONTEXT()"
                 "REPRESENTATION_CONTEXT('2D SPACE',''))")


def knots_mults(knots):
    ks, ms = [], []
    for k in knots:
        if ks and ks[-1] == k:
            ms[-1] += 1
        else:
            ks.append(k)
            ms.append(1)
    return ks, ms


def bspline_curve2d(s, degree, knots, pts, weights=None):
    ks, ms = knots_mults(knots)
    refs = ",".join(pt(s, *p) for p in pts)
    if weights is None:
        return s.add("B_SPLINE_CURVE_WITH_KNOTS('',%d,(%s),.UNSPECIFIED.,.F.,.F.,(%s),(%s),.UNSPECIFIED.)"
                     % (degree, refs, ",".join(map(str, ms)), ",".join(r(k) for k in ks)))
    return s.add("(BOUNDED_CURVE()B_SPLINE_CURVE(%d,(%s),.UNSPECIFIED.,.F.,.F.)B_SPLINE_CURVE_WITH_KNOTS((%s),(%s),"
                 ".UNSPECIFIED.)CURVE()GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_CURVE((%s))"
                 "REPRESENTATION_ITEM(''))" % (degree, refs, ",".join(map(str, ms)), ",".join(r(k) for k in ks),
                                              ",".join(r(w) for w in weights)))


def vec_line2d(s, p, d):
    v = s.add("VECTOR('',%s,1.)" % dirn(s, *d))
    return s.add("LINE('',%s,%s)" % (pt(s, *p), v))


def pcurve(s, surface, curve, c2):
    rep = s.add("DEFINITIONAL_REPRESENTATION('',(%s),%s)" % (curve, c2))
    return s.add("PCURVE('',%s,%s)" % (surface, rep))


def vertex(s, p):
    return s.add("VERTEX_POINT('',%s)" % pt(s, *p))


def edge(s, v0, v1, pcurves, same=True):
    c3 = s.add("LINE('',%s,%s)" % (pt(s, 0, 0, 0), s.add("VECTOR('',%s,1.)" % dirn(s, 1, 0, 0))))
    kind = "SEAM_CURVE" if len(pcurves) == 2 else "SURFACE_CURVE"
    sc = s.add("%s('',%s,(%s),.PCURVE_S1.)" % (kind, c3, ",".join(pcurves)))
    return s.add("EDGE_CURVE('',%s,%s,%s,%s)" % (v0, v1, sc, ".T." if same else ".F."))


def oriented(s, e, orientation=True):
    return s.add("ORIENTED_EDGE('',*,*,%s,%s)" % (e, ".T." if orientation else ".F."))


def loop(s, edges):
    return s.add("EDGE_LOOP('',(%s))" % ",".join(edges))


def face(s, surface, outer, holes=(), same=True):
    bounds = [s.add("FACE_OUTER_BOUND('',%s,.T.)" % outer)] + [s.add("FACE_BOUND('',%s,.T.)" % h) for h in holes]
    return s.add("ADVANCED_FACE('',(%s),%s,%s)" % (",".join(bounds), surface, ".T." if same else ".F."))


def line_loop(s, surface, c2, corners, point3d):
    """A loop of line pcurves through the (u, v) corners; point3d(u, v) gives the vertices."""
    vs = [vertex(s, point3d(*c)) for c in corners]
    edges = []
    for k in range(len(corners)):
        a, b = corners[k], corners[(k + 1) % len(corners)]
        d = (b[0] - a[0], b[1] - a[1])
        ln = vec_line2d(s, a, d)
        edges.append(oriented(s, edge(s, vs[k], vs[(k + 1) % len(vs)], [pcurve(s, surface, ln, c2)])))
    return loop(s, edges)


def shape(s, ctx, faces, name="part"):
    shell = s.add("OPEN_SHELL('',(%s))" % ",".join(faces))
    model = s.add("SHELL_BASED_SURFACE_MODEL('',(%s))" % shell)
    return s.add("MANIFOLD_SURFACE_SHAPE_REPRESENTATION('%s',(%s),%s)" % (name, model, ctx))


def sampler():
    s = Step()
    ctx = units(s)
    c2 = ctx2d(s)
    faces = []
    # 1. rational B-spline surface, degree 2 x 1, 3 x 2 points (a quarter cylinder of radius 2, height 3),
    #    trimmed by a square of four degree-1 B-spline pcurves inside [0,1]^2
    w = math.sqrt(0.5)
    rows = [[(2, 0, 0), (2, 0, 3)], [(2, 2, 0), (2, 2, 3)], [(0, 2, 0), (0, 2, 3)]]
    cps = "(%s)" % ",".join("(%s)" % ",".join(pt(s, *p) for p in row) for row in rows)
    quarter = s.add("(BOUNDED_SURFACE()B_SPLINE_SURFACE(2,1,%s,.UNSPECIFIED.,.F.,.F.,.F.)"
                    "B_SPLINE_SURFACE_WITH_KNOTS((3,3),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.)"
                    "GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_SURFACE(((1.,1.),(%s,%s),(1.,1.)))"
                    "REPRESENTATION_ITEM('')SURFACE())" % (cps, r(w), r(w)))
    sq = [(0.25, 0.25), (0.75, 0.25), (0.75, 0.75), (0.25, 0.75)]
    vs = [vertex(s, (0, 0, 0)) for _ in sq]
    edges = []
    for k in range(4):
        a, b = sq[k], sq[(k + 1) % 4]
        c = bspline_curve2d(s, 1, [0, 0, 1, 1], [a, b])
        edges.append(oriented(s, edge(s, vs[k], vs[(k + 1) % 4], [pcurve(s, quarter, c, c2)])))
    faces.append(face(s, quarter, loop(s, edges)))
    # 2. polynomial B-spline surface (simple instance), 4 x 3 points, degrees 3 x 2, its range
    #    [0.5, 2] x [0, 1] given by a rectangle of lines trimmed by parameter values
    knots_u, knots_v = [0, 0, 0, 0, 2, 2, 2, 2], [0, 0, 0, 1, 1, 1]
    rows = [[(i, j, 0.1 * i * j + 0.05 * i * i) for j in range(3)] for i in range(4)]
    cps = "(%s)" % ",".join("(%s)" % ",".join(pt(s, *p) for p in row) for row in rows)
    ku, mu = knots_mults(knots_u)
    kv, mv = knots_mults(knots_v)
    poly = s.add("B_SPLINE_SURFACE_WITH_KNOTS('',3,2,%s,.UNSPECIFIED.,.F.,.F.,.F.,(%s),(%s),(%s),(%s),.UNSPECIFIED.)"
                 % (cps, ",".join(map(str, mu)), ",".join(map(str, mv)), ",".join(r(k) for k in ku),
                    ",".join(r(k) for k in kv)))
    rect = [((0, 0.0), (1, 0), 0.5, 2.0), ((2.0, 0), (0, 1), 0.0, 1.0), ((0, 1.0), (1, 0), 2.0, 0.5),
            ((0.5, 0), (0, 1), 1.0, 0.0)]
    vs = [vertex(s, (0, 0, 0)) for _ in rect]
    edges = []
    for k, (p, d, t1, t2) in enumerate(rect):
        ln = vec_line2d(s, p, d)
        tc = s.add("TRIMMED_CURVE('',%s,(PARAMETER_VALUE(%s)),(PARAMETER_VALUE(%s)),%s,.PARAMETER.)"
                   % (ln, r(t1), r(t2), ".T." if t2 > t1 else ".F."))
        edges.append(oriented(s, edge(s, vs[k], vs[(k + 1) % 4], [pcurve(s, poly, tc, c2)])))
    faces.append(face(s, poly, loop(s, edges)))
    # 3. the plane z = -1 (x along +x), a 4 x 3 rectangle from (0,0) with a hole: the circle of radius 0.5
    #    around (1, 1) in (u, v)
    plane = s.add("PLANE('',%s)" % axis3(s, (0, 0, -1), (0, 0, 1), (1, 0, 0)))
    outer = line_loop(s, plane, c2, [(0, 0), (4, 0), (4, 3), (0, 3)], lambda u, v: (u, v, -1))
    hv = vertex(s, (1.5, 1, -1))
    circle = s.add("CIRCLE('',%s,0.5)" % s.add("AXIS2_PLACEMENT_2D('',%s,%s)" % (pt(s, 1, 1), dirn(s, 1, 0))))
    hole = loop(s, [oriented(s, edge(s, hv, hv, [pcurve(s, plane, circle, c2)]), False)])
    faces.append(face(s, plane, outer, [hole]))
    # 4. the cylinder of radius 1.5 about the axis through (5, 0, 0) along +z, 0 <= z <= 2, whole, with a seam
    cyl = s.add("CYLINDRICAL_SURFACE('',%s,1.5)" % axis3(s, (5, 0, 0), (0, 0, 1), (1, 0, 0)))
    v1, v2 = vertex(s, (6.5, 0, 0)), vertex(s, (6.5, 0, 2))
    bottom = edge(s, v1, v1, [pcurve(s, cyl, vec_line2d(s, (0, 0), (1, 0)), c2)])
    top = edge(s, v2, v2, [pcurve(s, cyl, vec_line2d(s, (0, 2), (1, 0)), c2)])
    seam = edge(s, v1, v2, [pcurve(s, cyl, vec_line2d(s, (0, 0), (0, 1)), c2),
                            pcurve(s, cyl, vec_line2d(s, (2 * math.pi, 0), (0, 1)), c2)])
    faces.append(face(s, cyl, loop(s, [oriented(s, bottom), oriented(s, seam), oriented(s, top, False),
                                        oriented(s, seam, False)])))
    # 5. the cone of radius 1 at z = 0, semi-angle 0.3, about (0, 10, 0) along +z: u in [0, pi], v in [0, 2]
    ca = 0.3
    cone = s.add("CONICAL_SURFACE('',%s,1.,%s)" % (axis3(s, (0, 10, 0), (0, 0, 1), (1, 0, 0)), r(ca)))
    rho = lambda v: 1 + v * math.tan(ca)
    faces.append(face(s, cone, line_loop(s, cone, c2, [(0, 0), (math.pi, 0), (math.pi, 2), (0, 2)],
                                         lambda u, v: (rho(v) * math.cos(u), 10 + rho(v) * math.sin(u), v))))
    # 6. the sphere of radius 2 about (0, 0, 10): u in [0, pi/2], v in [0, pi/4]
    sph = s.add("SPHERICAL_SURFACE('',%s,2.)" % axis3(s, (0, 0, 10), (0, 0, 1), (1, 0, 0)))
    sp = lambda u, v: (2 * math.cos(v) * math.cos(u), 2 * math.cos(v) * math.sin(u), 10 + 2 * math.sin(v))
    faces.append(face(s, sph, line_loop(s, sph, c2, [(0, 0), (math.pi / 2, 0), (math.pi / 2, math.pi / 4),
                                                     (0, math.pi / 4)], sp)))
    # 7. the torus R = 3, r = 1 about (10, 10, 0) along +z: u in [-pi/2, pi/2], v in [-pi/2, pi/2]
    tor = s.add("TOROIDAL_SURFACE('',%s,3.,1.)" % axis3(s, (10, 10, 0), (0, 0, 1), (1, 0, 0)))
    tp = lambda u, v: (10 + (3 + math.cos(v)) * math.cos(u), 10 + (3 + math.cos(v)) * math.sin(u), math.sin(v))
    h = math.pi / 2
    faces.append(face(s, tor, line_loop(s, tor, c2, [(-h, -h), (h, -h), (h, h), (-h, h)], tp)))
    # 8. a plane bounded by a 3-D line there and back only: skipped (projected, it encloses no area)
    pl = s.add("PLANE('',%s)" % axis3(s, (0, 0, 20), (0, 0, 1), (1, 0, 0)))
    a, b = vertex(s, (0, 0, 20)), vertex(s, (1, 0, 20))
    l3 = s.add("LINE('',%s,%s)" % (pt(s, 0, 0, 20), s.add("VECTOR('',%s,1.)" % dirn(s, 1, 0, 0))))
    e3 = s.add("EDGE_CURVE('',%s,%s,%s,.T.)" % (a, b, l3))
    faces.append(face(s, pl, loop(s, [oriented(s, e3), oriented(s, e3, False)])))
    # 9. the polynomial surface again, trimmed by a triangle of lines whose ends are found from the
    #    vertices (3-D points evaluated here by Bernstein sums: one span in each direction)
    def bern(n, i, t):
        return math.comb(n, i) * t ** i * (1 - t) ** (n - i)

    def poly_point(u, v):
        x = [0.0, 0.0, 0.0]
        for i in range(4):
            for j in range(3):
                b = bern(3, i, u / 2) * bern(2, j, v)
                for a in range(3):
                    x[a] += b * rows[i][j][a]
        return tuple(x)

    tri = [(0.5, 0.2), (1.8, 0.2), (1.0, 0.9)]
    vs = [vertex(s, poly_point(*c)) for c in tri]
    edges = []
    for k in range(3):
        a, b = tri[k], tri[(k + 1) % 3]
        ln = vec_line2d(s, (a[0] - 3 * (b[0] - a[0]), a[1] - 3 * (b[1] - a[1])), (b[0] - a[0], b[1] - a[1]))
        edges.append(oriented(s, edge(s, vs[k], vs[(k + 1) % 3], [pcurve(s, poly, ln, c2)])))
    faces.append(face(s, poly, loop(s, edges)))
    shape(s, ctx, faces)
    s.write("sampler.stp")


def inches():
    s = Step()
    ctx = units(s, inch=True)
    c2 = ctx2d(s)
    plane = s.add("PLANE('',%s)" % axis3(s, (0, 0, 0), (0, 0, 1), (1, 0, 0)))
    f = face(s, plane, line_loop(s, plane, c2, [(0, 0), (1, 0), (1, 1), (0, 1)], lambda u, v: (u, v, 0)))
    shape(s, ctx, [f])
    s.write("inches.stp")


def assembly():
    s = Step()
    ctx = units(s)
    c2 = ctx2d(s)
    plane = s.add("PLANE('',%s)" % axis3(s, (0, 0, 0), (0, 0, 1), (1, 0, 0)))
    f = face(s, plane, line_loop(s, plane, c2, [(0, 0), (1, 0), (1, 1), (0, 1)], lambda u, v: (u, v, 0)))
    part_origin = axis3(s, (0, 0, 0), (0, 0, 1), (1, 0, 0))
    part = shape(s, ctx, [f], "part")
    part_sr = s.add("SHAPE_REPRESENTATION('part',(%s),%s)" % (part_origin, ctx))
    s.add("SHAPE_REPRESENTATION_RELATIONSHIP('','',%s,%s)" % (part_sr, part))
    # the assembly: the part moved by (100, 0, 0), and turned a quarter about z and moved by (0, 50, 0)
    at1 = axis3(s, (100, 0, 0), (0, 0, 1), (1, 0, 0))
    at2 = axis3(s, (0, 50, 0), (0, 0, 1), (0, 1, 0))
    asm_origin = axis3(s, (0, 0, 0), (0, 0, 1), (1, 0, 0))
    asm = s.add("SHAPE_REPRESENTATION('assembly',(%s,%s,%s),%s)" % (asm_origin, at1, at2, ctx))
    for at in (at1, at2):
        idt = s.add("ITEM_DEFINED_TRANSFORMATION('','',%s,%s)" % (part_origin, at))
        s.add("(REPRESENTATION_RELATIONSHIP('','',%s,%s)REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(%s)"
              "SHAPE_REPRESENTATION_RELATIONSHIP())" % (part_sr, asm, idt))
    # a mapped item in another representation: the part moved up by 7
    target = axis3(s, (0, 0, 7), (0, 0, 1), (1, 0, 0))
    rmap = s.add("REPRESENTATION_MAP(%s,%s)" % (part_origin, part_sr))
    item = s.add("MAPPED_ITEM('',%s,%s)" % (rmap, target))
    s.add("SHAPE_REPRESENTATION('mapped',(%s),%s)" % (item, ctx))
    s.write("assembly.stp")


def edge3d(s, v0, v1, curve, same=True):
    return s.add("EDGE_CURVE('',%s,%s,%s,%s)" % (v0, v1, curve, ".T." if same else ".F."))


def circle3d(s, c, z, x, radius):
    return s.add("CIRCLE('',%s,%s)" % (axis3(s, c, z, x), r(radius)))


def line3d(s, p, d):
    return s.add("LINE('',%s,%s)" % (pt(s, *p), s.add("VECTOR('',%s,1.)" % dirn(s, *d))))


def band(s, surface, bottom, top, seam, a, b):
    """A whole turn between the closed curves bottom (through vertex a) and top (through b), the seam from a to b."""
    va, vb = vertex(s, a), vertex(s, b)
    e0, e1, e2 = edge3d(s, va, va, bottom), edge3d(s, va, vb, seam), edge3d(s, vb, vb, top)
    return loop(s, [oriented(s, e0), oriented(s, e1), oriented(s, e2, False), oriented(s, e1, False)])


def analytic3d():
    s = Step()
    ctx = units(s)
    faces = []
    # the cylinder of radius 2 about the z axis, z in [0, 3]; the window theta in [2, 3], z in [1, 2]
    cyl = s.add("CYLINDRICAL_SURFACE('',%s,2.)" % axis3(s, (0, 0, 0), (0, 0, 1), (1, 0, 0)))
    outer = band(s, cyl, circle3d(s, (0, 0, 0), (0, 0, 1), (1, 0, 0), 2), circle3d(s, (0, 0, 3), (0, 0, 1), (1, 0, 0), 2),
                 line3d(s, (2, 0, 0), (0, 0, 1)), (2, 0, 0), (2, 0, 3))
    cp = lambda th, z: (2 * math.cos(th), 2 * math.sin(th), z)

    def window(t1, t2, z1, z2):
        p11, p21, p22, p12 = (vertex(s, cp(t, z)) for t, z in ((t1, z1), (t2, z1), (t2, z2), (t1, z2)))
        low = edge3d(s, p11, p21, circle3d(s, (0, 0, z1), (0, 0, 1), (1, 0, 0), 2))
        high = edge3d(s, p12, p22, circle3d(s, (0, 0, z2), (0, 0, 1), (1, 0, 0), 2))
        up1 = edge3d(s, p11, p12, line3d(s, cp(t1, z1), (0, 0, 1)))
        up2 = edge3d(s, p21, p22, line3d(s, cp(t2, z1), (0, 0, 1)))
        return loop(s, [oriented(s, up1), oriented(s, high), oriented(s, up2, False), oriented(s, low, False)])
    # a second window past half a turn (theta in [4, 4.5], z in [1.2, 1.8]): its angles come out negative first
    faces.append(face(s, cyl, outer, [window(2, 3, 1, 2), window(4, 4.5, 1.2, 1.8)]))
    # the sphere of radius 2 about (10, 0, 0): u in [-1, 1.2], latitude in [-0.6, 0.9]; a hole of angular
    # radius 0.3 about the direction of (u, lat) = (0.1, 0.15)
    c = (10, 0, 0)
    sph = s.add("SPHERICAL_SURFACE('',%s,2.)" % axis3(s, c, (0, 0, 1), (1, 0, 0)))
    sp = lambda u, la: (c[0] + 2 * math.cos(la) * math.cos(u), 2 * math.cos(la) * math.sin(u), 2 * math.sin(la))
    corners = [vertex(s, sp(u, la)) for u, la in ((-1, -0.6), (1.2, -0.6), (1.2, 0.9), (-1, 0.9))]
    par = lambda la: circle3d(s, (c[0], 0, 2 * math.sin(la)), (0, 0, 1), (1, 0, 0), 2 * math.cos(la))
    mer = lambda u: circle3d(s, c, (math.sin(u), -math.cos(u), 0), (math.cos(u), math.sin(u), 0), 2)
    e_low = edge3d(s, corners[0], corners[1], par(-0.6))
    e_east = edge3d(s, corners[1], corners[2], mer(1.2))
    e_high = edge3d(s, corners[3], corners[2], par(0.9))
    e_west = edge3d(s, corners[0], corners[3], mer(-1))
    patch = loop(s, [oriented(s, e_low), oriented(s, e_east), oriented(s, e_high, False), oriented(s, e_west, False)])
    n = (math.cos(0.15) * math.cos(0.1), math.cos(0.15) * math.sin(0.1), math.sin(0.15))
    x = (-n[1], n[0], 0)
    xl = math.hypot(x[0], x[1])
    x = (x[0] / xl, x[1] / xl, 0)
    beta = 0.3
    centre = tuple(c[k] + 2 * math.cos(beta) * n[k] for k in range(3))
    vh = vertex(s, tuple(centre[k] + 2 * math.sin(beta) * x[k] for k in range(3)))
    hole = loop(s, [oriented(s, edge3d(s, vh, vh, circle3d(s, centre, n, x, 2 * math.sin(beta))), False)])
    faces.append(face(s, sph, patch, [hole]))
    # a surface of revolution about the z axis of the quadratic (1,0,0), (2.5,0,1), (1.5,0,2):
    # rho(z) = 1 + 1.5 z - 0.625 z^2; the whole turn between the parallels z = 0.5 and z = 1.5
    prof = bspline_curve2d(s, 2, [0, 0, 0, 1, 1, 1], [(1, 0, 0), (2.5, 0, 1), (1.5, 0, 2)])
    rev = s.add("SURFACE_OF_REVOLUTION('',%s,%s)" % (prof, s.add("AXIS1_PLACEMENT('',%s,%s)" % (pt(s, 0, 0, 0),
                                                                                             dirn(s, 0, 0, 1)))))
    rho = lambda z: 1 + 1.5 * z - 0.625 * z * z
    outer = band(s, rev, circle3d(s, (0, 0, 0.5), (0, 0, 1), (1, 0, 0), rho(0.5)),
                 circle3d(s, (0, 0, 1.5), (0, 0, 1), (1, 0, 0), rho(1.5)), prof, (rho(0.5), 0, 0.5), (rho(1.5), 0, 1.5))
    faces.append(face(s, rev, outer))
    # left out: an extrusion bounded by 3-D lines, and a sphere cap bounded by one parallel (no area in (u, v))
    ext = s.add("SURFACE_OF_LINEAR_EXTRUSION('',%s,%s)" % (line3d(s, (0, 0, 0), (1, 0, 0)),
                                                          s.add("VECTOR('',%s,1.)" % dirn(s, 0, 0, 1))))
    q = [vertex(s, p) for p in ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1))]
    es = [edge3d(s, q[k], q[(k + 1) % 4], line3d(s, p, d)) for k, (p, d) in
          enumerate((((0, 0, 0), (1, 0, 0)), ((1, 0, 0), (0, 0, 1)), ((1, 0, 1), (-1, 0, 0)), ((0, 0, 1), (0, 0, -1))))]
    faces.append(face(s, ext, loop(s, [oriented(s, e) for e in es])))
    cap = s.add("SPHERICAL_SURFACE('',%s,1.)" % axis3(s, (0, 0, 20), (0, 0, 1), (1, 0, 0)))
    vc = vertex(s, (math.cos(0.5), 0, 20 + math.sin(0.5)))
    ring = edge3d(s, vc, vc, circle3d(s, (0, 0, 20 + math.sin(0.5)), (0, 0, 1), (1, 0, 0), math.cos(0.5)))
    faces.append(face(s, cap, loop(s, [oriented(s, ring)])))
    shape(s, ctx, faces)
    s.write("analytic3d.stp")


sampler()
inches()
assembly()
analytic3d()
