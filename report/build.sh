#!/usr/bin/env bash
# Rebuilds dist/viewer.js, the three.js viewer of msmesh's HTML report, from src/viewer.js.
# Only needed after changing src/viewer.js or the three.js version: dist/viewer.js is
# committed, and the C++ build embeds it without needing node or npm.
set -euo pipefail
cd "$(dirname "$0")"
npm ci --no-audit --no-fund
npx esbuild src/viewer.js --bundle --minify --format=iife --target=es2020 --charset=ascii \
  --legal-comments=eof --outfile=dist/viewer.js
if grep -qi '</script' dist/viewer.js; then
  echo "report/build.sh: dist/viewer.js contains '</script' and cannot be inlined in the report" >&2
  exit 1
fi
size=$(wc -c < dist/viewer.js)
echo "report/build.sh: dist/viewer.js is $size bytes"
if [ "$size" -gt 1048576 ]; then
  echo "report/build.sh: dist/viewer.js is over 1 MiB" >&2
  exit 1
fi
