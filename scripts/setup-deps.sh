#!/usr/bin/env bash
# Installs the Debian packages in scripts/debian-packages.txt that are missing, and the npm tools the
# tests use (glTF validator, three.js). Safe to run again: it only installs what is absent.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

mapfile -t wanted < <(grep -v '^\s*#' "$here/debian-packages.txt" | awk 'NF{print $1}')
missing=()
for pkg in "${wanted[@]}"; do
  status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
  [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
done
# Node.js may come from elsewhere than Debian; only ask apt for it when there is none.
if ! command -v npm >/dev/null 2>&1; then missing+=(nodejs npm); fi

if [ ${#missing[@]} -gt 0 ]; then
  echo "gestura setup: installing Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null
fi

# npm tools, pinned in tools/package.json, installed into tools/node_modules (ignored by git);
# reinstalled when package.json is newer than node_modules, so existing checkouts get added tools.
if [ -f "$root/tools/package.json" ] &&
   { [ ! -d "$root/tools/node_modules" ] || [ "$root/tools/package.json" -nt "$root/tools/node_modules" ]; }; then
  echo "gestura setup: installing npm tools (tools/package.json)"
  (cd "$root/tools" && npm install --no-audit --no-fund --loglevel=error </dev/null)
  touch "$root/tools/node_modules"  # npm leaves its mtime alone when nothing changed
fi

# The web page's packages (three.js; puppeteer-core for its browser tests), pinned in web/package.json.
if [ -f "$root/web/package.json" ] &&
   { [ ! -d "$root/web/node_modules" ] || [ "$root/web/package.json" -nt "$root/web/node_modules" ]; }; then
  echo "gestura setup: installing the web page's npm packages (web/package.json)"
  (cd "$root/web" && if [ -f package-lock.json ]; then npm ci --no-audit --no-fund --loglevel=error; else npm install --no-audit --no-fund --loglevel=error; fi </dev/null)
  touch "$root/web/node_modules"
fi
