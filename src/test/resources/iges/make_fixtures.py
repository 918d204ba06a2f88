#!/usr/bin/env python3
"""Writes the IGES test fixtures of IgesReaderTest (and revolved3d.igs of ProjectedTrimTracingTest),
independently of the Java writer.

Run from this folder: python3 make_fixtures.py. Each entity is (type, form, status, params);
directory pointers are 2*index+1. The layout follows IGES 5.3 section 2 (80 columns, S/G/D/P/T).
"""
import math

def fmt(v):
    return repr(float(v)) if isinstance(v, float) else str(v)

def record(params):
    out, line = [], ""
    fields = [fmt(p) for p in params]
    for k, f in enumerate(fields):
        f += ";" if k == len(fields) - 1 else ","
        if len(line) + len(f) > 64:
            out.append(line)
            line = ""
        line += f
    out.append(line)
    return out

def write(path, entities, units=2, unit_name="MM", scale=1.0):
    lines = []
    s = ["Bezier Tracer test fixture written by make_fixtures.py"]
    for k, t in enumerate(s):
        lines.append("%-72sS%7d" % (t, k + 1))
    g = ["1H,", "1H;", "7HFIXTURE", "11Hfixture.igs", "6HPYTHON", "3H1.0", "32", "38", "6", "308", "15",
         "7HFIXTURE", repr(scale), str(units), "%dH%s" % (len(unit_name), unit_name), "1", "0.0",
         "15H20261205.000000", "1.0E-8", "0.0", "4HTEST", "4HTEST", "11", "0", "15H20261205.000000"]
    gl, line = [], ""
    for k, f in enumerate(g):
        f += ";" if k == len(g) - 1 else ","
        if len(line) + len(f) > 72:
            gl.append(line)
            line = ""
        line += f
    gl.append(line)
    for k, t in enumerate(gl):
        lines.append("%-72sG%7d" % (t, k + 1))
    pds = [record(e[3]) for e in entities]
    pd, d = 1, 0
    for (etype, form, status, params, *rest), p in zip(entities, pds):
        transform = rest[0] if rest else 0
        colour = rest[1] if len(rest) > 1 else 0
        d += 1
        lines.append("%8d%8d%8d%8d%8d%8d%8d%8d%8sD%7d" % (etype, pd, 0, 1, 0, 0, transform, 0, status, d))
        d += 1
        lines.append("%8d%8d%8d%8d%8d%8s%8s%8s%8dD%7d" % (etype, 0, colour, len(p), form, "", "", "ENTITY", 0, d))
        pd += len(p)
    n = 0
    for k, p in enumerate(pds):
        for t in p:
            n += 1
            lines.append("%-64s %7dP%7d" % (t, 2 * k + 1, n))
    lines.append("%-72sT%7d" % ("S%7dG%7dD%7dP%7d" % (len(s), len(gl), d, n), 1))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")

H = math.sqrt(0.5)
IND, DEP, PARAM = "00000000", "00010000", "00010500"
sampler = [
    (124, 0, IND, [124, 1.0, 0.0, 0.0, 10.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0]),                      # D1
    (128, 0, IND, [128, 2, 1, 2, 1, 0, 0, 0, 0, 0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0,      # D3
                   1.0, H, 1.0, 1.0, H, 1.0,
                   2.0, 0.0, 0.0, 2.0, 2.0, 0.0, 0.0, 2.0, 0.0, 2.0, 0.0, 3.0, 2.0, 2.0, 3.0, 0.0, 2.0, 3.0,
                   0.0, 1.0, 0.0, 1.0], 1),
    (128, 0, DEP, [128, 1, 1, 1, 1, 0, 0, 1, 0, 0, 0.0, 0.0, 4.0, 4.0, 0.0, 0.0, 4.0, 4.0,              # D5
                   1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 5.0, 4.0, 0.0, 5.0, 0.0, 4.0, 5.0, 4.0, 4.0, 5.0,
                   0.0, 4.0, 0.0, 4.0]),
    (110, 0, PARAM, [110, 1.0, 1.0, 0.0, 3.0, 1.0, 0.0]),                                                   # D7
    (110, 0, PARAM, [110, 3.0, 1.0, 0.0, 3.0, 3.0, 0.0]),                                                   # D9
    (110, 0, PARAM, [110, 3.0, 3.0, 0.0, 1.0, 3.0, 0.0]),                                                   # D11
    (110, 0, PARAM, [110, 1.0, 3.0, 0.0, 1.0, 1.0, 0.0]),                                                   # D13
    (102, 0, PARAM, [102, 4, 7, 9, 11, 13]),                                                                # D15
    (142, 0, DEP, [142, 0, 5, 15, 0, 1]),                                                                   # D17
    (100, 0, PARAM, [100, 0.0, 2.0, 2.0, 2.5, 2.0, 2.5, 2.0]),                                              # D19
    (142, 0, DEP, [142, 0, 5, 19, 0, 1]),                                                                   # D21
    (314, 0, "00000200", [314, 50.0, 25.0, 100.0, "6HPURPLE"]),                                             # D23
    (144, 0, IND, [144, 5, 1, 1, 17, 21], 0, -23),                                                          # D25
    (110, 0, DEP, [110, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]),                                                     # D27
    (110, 0, DEP, [110, 1.0, 0.0, 0.0, 1.0, 0.0, 2.0]),                                                     # D29
    (120, 0, IND, [120, 27, 29, 0.0, 2 * math.pi]),                                                         # D31
    (100, 0, DEP, [100, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 3.0]),                                                # D33
    (122, 0, IND, [122, 33, 3.0, 0.0, 4.0]),                                                                # D35
    (116, 0, IND, [116, 1.0, 2.0, 3.0, 0]),                                                                 # D37
    (212, 0, IND, [212, 0]),                                                                                # D39
    (128, 0, DEP, [128, 1, 1, 1, 1, 0, 0, 1, 0, 0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0,              # D41
                   1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0,
                   0.0, 1.0, 0.0, 1.0]),
    (308, 0, "00000200", [308, 0, "4HPART", 1, 41]),                                                        # D43
    (408, 0, IND, [408, 43, 0.0, 0.0, 100.0, 2.0]),                                                         # D45
    (100, 0, DEP, [100, -1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0]),                                               # D47
    (108, 1, IND, [108, 0.0, 0.0, 1.0, -1.0, 47, 0.0, 0.0, -1.0, 1.0]),                                     # D49
]
write("sampler.igs", sampler)

inches = [
    (128, 0, IND, [128, 1, 1, 1, 1, 0, 0, 1, 0, 0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0,
                   1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0,
                   0.0, 1.0, 0.0, 1.0]),
]
write("inches.igs", inches, units=1, unit_name="IN", scale=2.0)

# a 144 trimmed by model-space curves only (142s with BPTR = 0): the bilinear x = 10 u, y = 10 v,
# the square (2,2)..(8,8) of 110 lines in a 102, a hole of the 100 circle of radius 1 about (5,5)
edges3d = [
    (128, 0, DEP, [128, 1, 1, 1, 1, 0, 0, 1, 0, 0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0,              # D1
                   1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 10.0, 0.0, 0.0, 0.0, 10.0, 0.0, 10.0, 10.0, 0.0,
                   0.0, 1.0, 0.0, 1.0]),
    (110, 0, DEP, [110, 2.0, 2.0, 0.0, 8.0, 2.0, 0.0]),                                                     # D3
    (110, 0, DEP, [110, 8.0, 2.0, 0.0, 8.0, 8.0, 0.0]),                                                     # D5
    (110, 0, DEP, [110, 8.0, 8.0, 0.0, 2.0, 8.0, 0.0]),                                                     # D7
    (110, 0, DEP, [110, 2.0, 8.0, 0.0, 2.0, 2.0, 0.0]),                                                     # D9
    (102, 0, DEP, [102, 4, 3, 5, 7, 9]),                                                                    # D11
    (142, 0, DEP, [142, 0, 1, 0, 11, 2]),                                                                   # D13
    (100, 0, DEP, [100, 0.0, 5.0, 5.0, 6.0, 5.0, 6.0, 5.0]),                                                # D15
    (142, 0, DEP, [142, 0, 1, 0, 15, 2]),                                                                   # D17
    (144, 0, IND, [144, 1, 1, 1, 13, 17]),                                                                  # D19
]
write("edges3d.igs", edges3d)

# a whole turn of a cone (a 120 of the line (1,0,0)-(2,0,2) about z: rho = 1 + z/2) trimmed by a 144
# whose only boundary is a window hole of model-space curves (a 142 with BPTR = 0): the parallel arc
# z = 0.5 from theta 2 to 3 (100), the meridian theta = 3 up (110), the parallel z = 1.5 back from
# theta 3 to 2 (126, a rational quadratic run clockwise), the meridian theta = 2 down (110)
def cone_point(theta, z):
    rho = 1 + z / 2
    return (rho * math.cos(theta), rho * math.sin(theta), z)

T1, T2, Z1, Z2 = 2.0, 3.0, 0.5, 1.5
R2, HALF = 1 + Z2 / 2, (T2 - T1) / 2
revolved3d = [
    (110, 0, DEP, [110, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]),                                                     # D1
    (110, 0, DEP, [110, 1.0, 0.0, 0.0, 2.0, 0.0, 2.0]),                                                     # D3
    (120, 0, DEP, [120, 1, 3, 0.0, 2 * math.pi]),                                                           # D5
    (100, 0, DEP, [100, Z1, 0.0, 0.0] + list(cone_point(T1, Z1)[:2]) + list(cone_point(T2, Z1)[:2])),       # D7
    (110, 0, DEP, [110] + list(cone_point(T2, Z1)) + list(cone_point(T2, Z2))),                             # D9
    (126, 0, DEP, [126, 2, 2, 1, 0, 0, 0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, math.cos(HALF), 1.0]           # D11
     + list(cone_point(T2, Z2))
     + [R2 / math.cos(HALF) * math.cos(T1 + HALF), R2 / math.cos(HALF) * math.sin(T1 + HALF), Z2]
     + list(cone_point(T1, Z2)) + [0.0, 1.0, 0.0, 0.0, 1.0]),
    (110, 0, DEP, [110] + list(cone_point(T1, Z2)) + list(cone_point(T1, Z1))),                             # D13
    (102, 0, DEP, [102, 4, 7, 9, 11, 13]),                                                                  # D15
    (142, 0, DEP, [142, 0, 5, 0, 15, 2]),                                                                   # D17
    (144, 0, IND, [144, 5, 0, 1, 0, 17]),                                                                   # D19
]
write("revolved3d.igs", revolved3d)
