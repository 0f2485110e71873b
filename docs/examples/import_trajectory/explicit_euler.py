#!/usr/bin/env python3
"""A program beachball never saw: explicit Euler on a case of falling balls in still air.

Reads the case file (gravity, [air] density, each sphere's radius, mass, drag coefficient,
position and velocity), steps every body with its own explicit Euler at the case's three
largest steps, and writes one trajectory file per step in beachball's format
(docs/output-files.md#trajectories), with the program's own time per step as cost_ns.
It prints the options that bring the files in:

    python3 explicit_euler.py cases/drag_fall.toml out/euler
    beachball run cases/drag_fall.toml --trajectory euler@1/30=out/euler/euler@1-30.csv ...

Standard library only (Python 3.11 or later, for tomllib). It knows gravity and quadratic
drag, F = -1/2 rho Cd (pi r^2) |v| v, and nothing else: a case with a ground, springs or
wind is not its business.
"""

import math
import os
import sys
import time
import tomllib


def step_name(dt):
    """The step as beachball names it in a file: 1-60 for 1/60 s."""
    rate = 1.0 / dt
    if abs(rate - round(rate)) < 1e-6 * rate:
        return "1-%d" % round(rate), "1/%d" % round(rate)
    return "%g" % dt, "%g" % dt


def simulate(case, dt, path):
    """Steps the case at dt to its duration, writing every step's rows to path."""
    gravity = case.get("gravity", [0.0, -9.81, 0.0])
    density = case.get("air", {}).get("density", 0.0)
    bodies = []
    for b in case["body"]:
        k = 0.5 * density * b.get("drag_coefficient", 0.0) * math.pi * b["radius"] ** 2
        bodies.append({"name": b["name"], "mass": b["mass"], "k": k,
                       "x": list(b["position"]), "v": list(b.get("velocity", [0.0] * 3))})
    steps = round(case["duration"] / dt)
    with open(path, "w", newline="\n") as out:
        out.write("t,body,x,y,z,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz,cost_ns\n")
        cost_ns = 0
        for n in range(steps + 1):
            t = n * dt  # a step count times dt, never a running sum
            for b in bodies:
                values = b["x"] + b["v"] + [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
                out.write("%r,%s,%s,%d\n" % (t, b["name"], ",".join(repr(v) for v in values),
                                             cost_ns))
            if n == steps:
                break
            start = time.perf_counter_ns()
            for b in bodies:
                speed = math.sqrt(sum(c * c for c in b["v"]))
                a = [g - b["k"] / b["mass"] * speed * c for g, c in zip(gravity, b["v"])]
                b["x"] = [x + dt * v for x, v in zip(b["x"], b["v"])]
                b["v"] = [v + dt * ai for v, ai in zip(b["v"], a)]
            cost_ns = time.perf_counter_ns() - start


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: explicit_euler.py CASE.toml OUTPUT_FOLDER")
    with open(sys.argv[1], "rb") as f:
        case = tomllib.load(f)
    os.makedirs(sys.argv[2], exist_ok=True)
    options = []
    for dt in sorted(case["dt"], reverse=True)[:3]:
        file_part, option_part = step_name(dt)
        path = os.path.join(sys.argv[2], "euler@%s.csv" % file_part)
        simulate(case, dt, path)
        options.append("--trajectory euler@%s=%s" % (option_part, path))
    print(" ".join(options))


if __name__ == "__main__":
    main()
