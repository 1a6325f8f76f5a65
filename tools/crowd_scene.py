#!/usr/bin/env python3
"""Writes a scene of N balls crowded into one spot, the broad phase's worst case
(docs/collisions.md, "Broad phase"): every ball's box overlaps every other's.

    tools/crowd_scene.py 10000 > crowd.xml
    /usr/bin/time -v build/release/bin/FOSSSim -s crowd.xml -d 0 -q

Options: --collision (penalty, simple, ...; default penalty), --steps (default 3),
--detection allpairs (to time all pairs on the same scene), --seed.
"""
import argparse
import random


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("count", type=int)
    parser.add_argument("--collision", default="penalty")
    parser.add_argument("--steps", type=int, default=3)
    parser.add_argument("--detection", choices=["default", "allpairs"], default="default")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    dt = 0.001
    lines = ["<scene>",
             f'  <duration time="{args.steps * dt!r}"/>',
             f'  <integrator type="symplectic-euler" dt="{dt!r}"/>']
    for _ in range(args.count):
        x, y = rng.uniform(-0.01, 0.01), rng.uniform(-0.01, 0.01)
        vx, vy = rng.uniform(-1, 1), rng.uniform(-1, 1)
        lines.append(f'  <particle m="1" px="{x!r}" py="{y!r}" vx="{vx!r}" vy="{vy!r}" '
                     'fixed="0" radius="0.1"/>')
    lines.append(f'  <collision type="{args.collision}"/>')
    if args.detection == "allpairs":
        lines.append('  <collisiondetection type="allpairs"/>')
    lines.append("</scene>")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
