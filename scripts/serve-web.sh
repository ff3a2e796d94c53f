#!/usr/bin/env bash
# Builds the wasm package and the demo pages, then serves them on http://127.0.0.1:8080/
# (PORT=8000 ./scripts/serve-web.sh for another port; HOST=0.0.0.0 to serve other machines).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/web-build.sh"
exec node "$root/web/serve.mjs" --port "${PORT:-8080}" --host "${HOST:-127.0.0.1}"
