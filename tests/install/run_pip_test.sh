#!/usr/bin/env bash
# ctest pip_install (labels install, pip; `ctest -L pip` runs it alone): what a new user does.
# A fresh virtual environment of Debian's Python that sees Debian's numpy, then
#   V/bin/pip install -v --no-build-isolation SOURCE
# offline (no package index), and from another folder: the msmesh command, python -m msmesh,
# import msmesh; then a wheel (pip wheel) installed into a second fresh environment, and
# pip uninstall. The sources must stay untouched. It compiles the project once more (ccache
# helps when installed); MSMESH_BUILD_JOBS (default 2) sets the parallel jobs.
#   run_pip_test.sh SOURCE_DIR WORK_DIR
# Exit status 77 (skipped) when venv or pip is missing (Debian: python3-venv python3-pip).
set -euo pipefail
src=$(cd "$1" && pwd)
work=$2
py=/usr/bin/python3
if ! $py -c 'import importlib.util as u, sys; sys.exit(not all(u.find_spec(m) for m in ("venv", "ensurepip", "pip", "setuptools", "wheel")))'; then
  echo "pip_install: SKIPPED: needs python3-venv python3-pip python3-setuptools python3-wheel (scripts/deps)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work/elsewhere"
work=$(cd "$work" && pwd)
export MSMESH_BUILD_DIR=$work/cmake-build MSMESH_BUILD_JOBS=${MSMESH_BUILD_JOBS:-2}
export PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1
unset PYTHONPATH MSMESH_CLI
fail() { echo "FAIL: $*"; exit 1; }

# What the sources hold before (to check that the build writes nothing there): every path
# outside .git and the top-level build folders, with its modification time.
# setuptools' own folders would be build/lib.*, build/temp.*, build/bdist.*: listed too.
snapshot() {
  (cd "$src" && find . \( -path ./.git -o -path './build*' -o -path ./out \) -prune -o -printf '%p %T@\n' | sort &&
    ls -d build*/lib.* build*/temp.* build*/bdist.* 2>/dev/null || true)
}
snapshot >"$work/before.txt"

echo "== fresh venv; pip install -v --no-build-isolation $src"
$py -m venv --system-site-packages "$work/venv"
V=$work/venv
start=$(date +%s)
"$V/bin/pip" install -v --no-build-isolation "$src" 2>&1 | tee "$work/pip.log" | grep --line-buffered -E '^\[[0-9]+/[0-9]+\]|msmesh setup.py|Successfully' || true
[ "${PIPESTATUS[0]}" = 0 ] || { tail -n 40 "$work/pip.log"; fail "pip install failed (log: $work/pip.log)"; }
echo "pip install took $(( $(date +%s) - start )) s"
snapshot >"$work/after.txt"
diff "$work/before.txt" "$work/after.txt" || fail "pip install wrote into the source tree (above)"

echo "== from another folder"
cd "$work/elsewhere"
[ -x "$V/bin/msmesh" ] || fail "no $V/bin/msmesh"
version=$("$V/bin/python" -c 'import msmesh, importlib.metadata as m; print(msmesh.__version__, m.version("msmesh"))')
echo "module and distribution: $version"
[ "$version" = "$(sed -n 's/^project(msmesh VERSION \([0-9.]*\).*/\1 \1/p' "$src/CMakeLists.txt")" ] ||
  fail "versions differ from CMakeLists.txt: $version"
[ "$("$V/bin/msmesh" --version)" = "msmesh ${version%% *}" ] || fail "msmesh --version: $("$V/bin/msmesh" --version)"
"$V/bin/python" -c "import msmesh, sys; assert msmesh.__file__.startswith('$V/'), msmesh.__file__; print('import msmesh:', msmesh.__file__)"
PATH=$V/bin:$PATH
msmesh shape fandisk --resolution 10 -o clean.obj -q
msmesh noise clean.obj -o noisy.obj --sigma 0.3 --seed 1 -q
msmesh denoise noisy.obj -o denoised.obj --truth clean.obj
"$V/bin/python" -m msmesh denoise noisy.obj -o module.obj -q
cmp denoised.obj module.obj || fail "python -m msmesh denoise differs from msmesh denoise"
"$V/bin/python" -m msmesh --help | grep -q denoise || fail "python -m msmesh --help"
"$V/bin/python" -c "
import msmesh
V, F = msmesh.read_mesh('noisy.obj')
V2, report = msmesh.denoise(V, F)
W, _ = msmesh.read_mesh('denoised.obj')
assert abs(V2 - W).max() < 1e-5 * abs(W).max(), abs(V2 - W).max()
print('msmesh.denoise from Python: preset', report['preset'], '- same as the program')"
# The same exit statuses: 2 a usage error, 1 a failed work.
# shellcheck disable=SC2086  # $args: the words of one command line
for args in "nosuchcommand" "denoise missing.obj -o out.obj"; do
  a=0; msmesh $args 2>/dev/null || a=$?
  b=0; "$V/bin/python" -m msmesh $args 2>/dev/null || b=$?
  echo "msmesh $args: exit $a; python -m msmesh: exit $b"
  [ "$a" = "$b" ] && [ "$a" != 0 ] || fail "exit statuses of 'msmesh $args' differ or are 0"
done
[ "$(msmesh nosuchcommand 2>/dev/null; echo $?)" = 2 ] || fail "a usage error is not status 2"

echo "== pip wheel --no-build-isolation --no-deps (the same CMake folder: incremental), into a second venv"
cd "$work"
"$V/bin/pip" wheel -q --no-build-isolation --no-deps -w "$work/wheels" "$src" >"$work/wheel.log" 2>&1 ||
  { tail -n 30 "$work/wheel.log"; fail "pip wheel failed"; }
wheel=$(ls "$work"/wheels/msmesh-*.whl)
echo "$wheel: $(du -k "$wheel" | cut -f1) KB"
"$V/bin/python" - "$wheel" <<'PY'
import sys, zipfile
names = {i.filename: i for i in zipfile.ZipFile(sys.argv[1]).infolist()}
program = names.get("msmesh/_bin/msmesh")
assert program is not None and (program.external_attr >> 16) & 0o111, "no executable msmesh/_bin/msmesh"
assert any(n.startswith("msmesh/_core") and n.endswith(".so") for n in names), "no extension"
assert any(n.endswith(".dist-info/LICENSE") for n in names), "no LICENSE"
meta = next(zipfile.ZipFile(sys.argv[1]).read(n).decode() for n in names if n.endswith(".dist-info/METADATA"))
assert "License: GPL-3.0-or-later" in meta, "licence metadata"
print("wheel holds the program, the extension, LICENSE and the licence metadata")
PY
$py -m venv --system-site-packages "$work/venv2"
"$work/venv2/bin/pip" install -q "$wheel"
(cd "$work/elsewhere" && "$work/venv2/bin/msmesh" info clean.obj >/dev/null && "$work/venv2/bin/python" -m msmesh --version &&
  "$work/venv2/bin/python" -c 'import msmesh; msmesh.make_shape("cube", 4)') || fail "the wheel's install does not run"
snapshot >"$work/after.txt"
diff "$work/before.txt" "$work/after.txt" || fail "pip wheel wrote into the source tree (above)"

echo "== pip uninstall"
"$V/bin/pip" uninstall -q -y msmesh
[ ! -e "$V/bin/msmesh" ] || fail "pip uninstall left $V/bin/msmesh"
rm -rf "$work/venv" "$work/venv2" "$work/elsewhere" "$work/wheels"
echo "pip_install: OK"
