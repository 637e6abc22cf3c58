#!/usr/bin/env bash
# Installs the npm side of GamePhysics into tools/web/node_modules when it is missing: KaTeX, which
# `gamephysics verify` and `gamephysics audit` inline into the audit page, and playwright-core,
# which drives Debian's chromium in the browser tests (tests/browser/). Exact versions from the
# committed package-lock.json (npm ci).
set -euo pipefail
cd "$(dirname "$0")/web"
if [[ ! -d node_modules/katex || ! -d node_modules/playwright-core ]]; then
  if ! command -v npm > /dev/null; then
    echo "install-web: npm not found; the audit page shows LaTeX source and the browser tests are skipped" >&2
    exit 0
  fi
  npm ci --no-audit --no-fund
fi
