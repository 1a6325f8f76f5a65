#!/bin/bash
# Makes the zip to upload to Gradescope ("Zip file upload" autograder):
#   autograder/make-zip.sh [OUTPUT.zip]      (default build/fosssim-autograder.zip)
# It holds setup.sh and run_autograder at its top, as Gradescope wants, and fosssim/: the
# repository's committed files at HEAD (git archive), which setup.sh builds. Uncommitted changes
# are not in it. Also `cmake --build --preset release --target autograder-zip`.
set -eu
kit=$(cd "$(dirname "$0")" && pwd)
repo=$(git -C "$kit" rev-parse --show-toplevel)
output=$(realpath -m "${1:-$repo/build/fosssim-autograder.zip}")
mkdir -p "$(dirname "$output")"
staging=$(mktemp -d)
trap 'rm -rf "$staging"' EXIT
git -C "$repo" archive --format=tar --prefix=fosssim/ HEAD > "$staging/fosssim.tar"
python3 - "$staging/fosssim.tar" "$kit" "$output" <<'PY'
import os, stat, sys, tarfile, zipfile
tar_path, kit, output = sys.argv[1:4]
def add(archive, name, data, mode):
    info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
    info.external_attr = (stat.S_IFREG | mode) << 16
    info.compress_type = zipfile.ZIP_DEFLATED
    archive.writestr(info, data)
with zipfile.ZipFile(output + ".tmp", "w") as archive:
    for name in ("setup.sh", "run_autograder"):
        with open(os.path.join(kit, name), "rb") as f:
            add(archive, name, f.read(), 0o755)
    with tarfile.open(tar_path) as tar:
        for member in tar:
            if member.isfile():
                add(archive, member.name, tar.extractfile(member).read(), member.mode & 0o777)
            elif member.issym():
                info = zipfile.ZipInfo(member.name, date_time=(2020, 1, 1, 0, 0, 0))
                info.external_attr = (stat.S_IFLNK | 0o777) << 16
                archive.writestr(info, member.linkname)
os.replace(output + ".tmp", output)
PY
echo "make-zip.sh: wrote $output ($(du -h "$output" | cut -f1))"
