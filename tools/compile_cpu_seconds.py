#!/usr/bin/env python3
"""CPU seconds (user + sys) to compile chosen units of a configured build, without building it.

    tools/compile_cpu_seconds.py BUILD_DIR OUT.tsv REGEX...

Compiles every entry of BUILD_DIR/compile_commands.json whose object file matches one of the
regular expressions (e.g. 'io_tests.dir/'), two at a time, each under /usr/bin/time, writes one
line per unit (CPU seconds, exit status, source) to OUT.tsv and prints the total. CPU seconds, not
wall time, so that figures taken on a loaded machine compare. Configure BUILD_DIR without a
compiler launcher (-DCMAKE_CXX_COMPILER_LAUNCHER=) so that ccache does not answer from its cache;
with FOSSSIM_UNITY_BUILD=ON the units are CMake's unity batches, with OFF the files themselves.
"""
import concurrent.futures
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile


def compile_unit(entry):
    command = shlex.split(entry['command'])
    output = command[command.index('-o') + 1]
    os.makedirs(os.path.join(entry['directory'], os.path.dirname(output)), exist_ok=True)
    with tempfile.NamedTemporaryFile('r') as times:
        result = subprocess.run(['/usr/bin/time', '-f', '%U %S', '-o', times.name] + command,
                                cwd=entry['directory'], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        user, system = map(float, times.read().split()[-2:])
    return entry['file'], result.returncode, user + system


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    build, out = sys.argv[1], sys.argv[2]
    patterns = [re.compile(p) for p in sys.argv[3:]]
    with open(os.path.join(build, 'compile_commands.json')) as f:
        entries = [e for e in json.load(f)
                   if any(p.search(e.get('output', e['command'])) for p in patterns)]
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        results = list(pool.map(compile_unit, entries))
    with open(out, 'w') as f:
        for source, status, cpu in results:
            f.write(f'{cpu:.2f}\t{status}\t{source}\n')
    failed = sum(1 for _, status, _ in results if status)
    print(f'{len(results)} units, {sum(cpu for _, _, cpu in results):.1f} CPU-s, {failed} failed')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
