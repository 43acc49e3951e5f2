#!/usr/bin/env bash
# Installs the browser tests' one npm package (playwright-core, the version package-lock.json pins)
# into tests/web/node_modules, once: nothing to do when it is there already. The browser is
# Debian's chromium (scripts/env/deps.sh), so Playwright downloads none.
set -euo pipefail
cd "$(dirname "$0")"
command -v npm >/dev/null || { echo "tests/web: npm is missing (Debian: apt-get install -y npm)" >&2; exit 1; }
want=$(node -p "require('./package-lock.json').packages['node_modules/playwright-core'].version")
have=$(node -p "try { require('./node_modules/playwright-core/package.json').version } catch { '' }")
if [ "$want" != "$have" ]; then
  PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund
fi
echo "playwright-core $want in $(pwd)/node_modules"
