#!/usr/bin/env bash
# Derives the editors' copies of the tree-sitter queries from the one source,
# tree-sitter-rapid/queries/. Never edit the copies by hand.
#
#   bash editors/sync-queries.sh           rewrite the copies
#   bash editors/sync-queries.sh --check   fail if a copy is stale (CI)
#
# Neovim: editors/neovim/queries/rapid/{highlights,folds,indents,locals,injections}.scm,
# copied with a header: the capture names are already Neovim's (@keyword,
# @function.call, ...), and Neovim reads the #match? patterns as very-magic
# Vim regexes, in which ^ $ ( | ) [...] mean what they mean to tree-sitter.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
src="$here/../tree-sitter-rapid/queries"
dst="$here/neovim/queries/rapid"
check=false
case "${1:-}" in
  --check) check=true ;;
  "") ;;
  *) echo "usage: $0 [--check]" >&2; exit 2 ;;
esac

derive() { # $1 = query file name
  printf ';; Generated from tree-sitter-rapid/queries/%s by editors/sync-queries.sh: do not edit.\n\n' "$1"
  cat "$src/$1"
}

stale=0
wanted=()
for name in highlights.scm folds.scm indents.scm locals.scm injections.scm; do
  [ -f "$src/$name" ] || continue
  wanted+=("$name")
  if $check; then
    if ! derive "$name" | cmp -s - "$dst/$name"; then
      echo "error: editors/neovim/queries/rapid/$name is stale: run 'bash editors/sync-queries.sh'" >&2
      stale=1
    fi
  else
    mkdir -p "$dst"
    derive "$name" >"$dst/$name"
  fi
done
# copies whose source is gone
for copy in "$dst"/*.scm; do
  [ -e "$copy" ] || continue
  base="$(basename "$copy")"
  if [[ ! " ${wanted[*]} " == *" $base "* ]]; then
    if $check; then
      echo "error: editors/neovim/queries/rapid/$base has no source in tree-sitter-rapid/queries/" >&2
      stale=1
    else
      rm -f "$copy"
    fi
  fi
done
if $check; then
  [ "$stale" = 0 ] || exit 1
  echo "editor queries are current (${#wanted[@]} files)"
else
  echo "wrote ${#wanted[@]} query files to editors/neovim/queries/rapid/"
fi
