#!/usr/bin/env python3
"""Writes bench_implicit's 2D damped cloth (bench/bench_scenes.h, damped_cloth_2d) as a course
XML scene, so that a large scene can be read the way a user's is: nx x nx particles, 1 m
square, hanging from the two corners of the top row, 1 kg in all, structural and shear springs
of 1000 N/m damped with 0.5 N s/m, gravity, linearized implicit Euler at h = 0.01 s.

    tools/scenes/damped_cloth_xml.py 316 > cloth316.xml    # about 55 MB
"""
import sys


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 316
    if n < 2:
        sys.exit("damped_cloth_xml.py: the size must be at least 2")
    out = sys.stdout
    step = 1.0 / (n - 1)
    mass = 1.0 / (n * n)
    out.write("<scene>\n")
    out.write('  <description text="A %dx%d damped cloth (tools/scenes/damped_cloth_xml.py)."/>\n'
              % (n, n))
    out.write('  <duration time="0.2"/>\n')
    out.write('  <integrator type="linearized-implicit-euler" dt="0.01"/>\n')
    out.write('  <maxsimfreq max="100"/>\n')
    for r in range(n):
        for c in range(n):
            fixed = 1 if r == 0 and c in (0, n - 1) else 0
            out.write('  <particle m="%r" px="%r" py="%r" vx="0" vy="0" fixed="%d" radius="0.001"/>\n'
                      % (mass, -0.5 + c * step, -r * step, fixed))
    springs = []
    for r in range(n):
        for c in range(n):
            p = r * n + c
            if c + 1 < n:
                springs.append((p, p + 1, step))
            if r + 1 < n:
                springs.append((p, p + n, step))
            if r + 1 < n and c + 1 < n:
                springs.append((p, p + n + 1, step * 2 ** 0.5))
                springs.append((p + 1, p + n, step * 2 ** 0.5))
    for i, j, _ in springs:
        out.write('  <edge i="%d" j="%d"/>\n' % (i, j))
    for e, (_, _, l0) in enumerate(springs):
        out.write('  <springforce edge="%d" k="1000" l0="%r" b="0.5"/>\n' % (e, l0))
    out.write('  <simplegravity fx="0" fy="-9.8"/>\n')
    out.write("</scene>\n")


if __name__ == "__main__":
    main()
