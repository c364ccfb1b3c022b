#!/usr/bin/env bash
# End-to-end test of the Neovim plugin in a real headless Neovim.
#   RAPID_BIN=/path/to/rapid NVIM=/path/to/nvim [RAPID_OUT=dir] bash editors/neovim/test/run.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
plugin="$(dirname "$here")"
repo="$(cd "$plugin/../.." && pwd)"
: "${RAPID_BIN:?set RAPID_BIN to the rapid binary}"
NVIM="${NVIM:-nvim}"
out="${RAPID_OUT:-$repo/tests/output}"
mkdir -p "$out"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

node "$repo/editors/e2e-workspace.mjs" "$tmp/workspace" >/dev/null
# isolated config, data and state: nothing of the user's setup is read
export XDG_CONFIG_HOME="$tmp/config" XDG_DATA_HOME="$tmp/data" XDG_STATE_HOME="$tmp/state" XDG_CACHE_HOME="$tmp/cache"
export RAPID_BIN RAPID_WS="$tmp/workspace" RAPID_NVIM_LOG="$out/neovim-e2e.log"
export PATH="$(dirname "$RAPID_BIN"):$PATH"
# --clean: no user config, but plugins on 'runtimepath' load (ours is prepended)
"$NVIM" --headless --clean --cmd "set runtimepath^=$plugin" -c "luafile $here/e2e.lua"
