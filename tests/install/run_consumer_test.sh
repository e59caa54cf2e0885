#!/usr/bin/env bash
# ctest install_consumer: `cmake --install` of a build into a fresh prefix, then a project outside
# the tree (tests/install/consumer) finds it with find_package(msmesh), builds against
# msmesh::io / msmesh::core, and denoises a mesh; its result must be the installed program's.
#   run_consumer_test.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix

echo "== cmake --install $build --prefix $prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in include/msmesh/denoise.h include/msmesh/io.h include/msmesh/read_mesh.h bin/msmesh; do
  [ -e "$prefix/$f" ] || { echo "FAIL: $prefix/$f was not installed"; exit 1; }
done
config=$(find "$prefix" -name msmeshConfig.cmake)
version=$(find "$prefix" -name msmeshConfigVersion.cmake)
[ -n "$config" ] && [ -n "$version" ] || { echo "FAIL: no msmeshConfig.cmake / msmeshConfigVersion.cmake"; exit 1; }
ls "$(dirname "$config")/../.."/libmsmesh_core.a "$(dirname "$config")/../.."/libmsmesh_io.a

echo "== the consumer project against $prefix"
gen=()
command -v ninja >/dev/null && gen=(-G Ninja)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$here/consumer" -B "$work/consumer" "${gen[@]}" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON | tee "$work/configure.log"
grep -q "found in $prefix/" "$work/configure.log" || { echo "FAIL: msmesh was not found in $prefix"; exit 1; }
# The build must use the installed headers, not the source tree's.
cmake --build "$work/consumer" -- -v | tee "$work/build.log" | tail -n 3
source=$(cd "$here/../.." && pwd)
grep -q -- "$prefix/include" "$work/build.log" || { echo "FAIL: $prefix/include is not on the compile line"; exit 1; }
if grep -q -F -e "$source/include" -e "$source/io/include" "$work/build.log"; then
  echo "FAIL: the consumer was compiled with the source tree's headers ($source)"
  exit 1
fi

echo "== the consumer denoises a mesh as the installed program does"
m=$prefix/bin/msmesh
"$m" --version
"$m" shape fandisk --resolution 12 -o "$work/clean.obj" -q
"$m" noise "$work/clean.obj" -o "$work/noisy.obj" --sigma 0.3 --seed 1 -q
"$work/consumer/msmesh_consumer" "$work/noisy.obj" "$work/consumer.obj"
"$m" denoise "$work/noisy.obj" -o "$work/program.obj" -q
cmp "$work/consumer.obj" "$work/program.obj" || { echo "FAIL: consumer and program results differ"; exit 1; }
status=0
"$work/consumer/msmesh_consumer" "$work/missing.obj" "$work/never.obj" 2>"$work/error.txt" || status=$?
[ "$status" = 1 ] && grep -q "missing.obj" "$work/error.txt" || { echo "FAIL: a missing input gave status $status"; exit 1; }
echo "install_consumer: OK"
