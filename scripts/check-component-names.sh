#!/usr/bin/env bash
# Where the knowledge of each component type lives. A component type's name string ("pdu",
# "torque_shaft", ...) may occur outside its own file(s) in model/src/components/ (which hold its
# declaration and its model; registry.cc lists them by their C++ names) only in examples, docs,
# tests, the database seed and benchmarks. This script lists every other source file that still
# names a type.
#
# Usage: scripts/check-component-names.sh [module ...]
#   With modules (e.g. "model sim export"), only their folders are checked and the exit status
#   is 1 when a type name occurs there: tests/model/component_names_test runs it that way for
#   the modules that are done. Without arguments every module is listed (exit status 0): the
#   report of what is left.
# Scenario kinds ("jam", "rupture") share a spelling with the jam type: lines that compare a
# scenario kind (`kind`) are not counted, nor are comments.
set -euo pipefail
# Files where a type's name is another thing's name, file:type (not a use of the type).
allowed=(
  "sim/src/gear_elements.cc:jam"          # the input port "jam" of the Jam element
  "core/src/element_types_gears.cc:jam"   # its declaration
  "core/include/highlift/core/project.h:jam"  # kJamKind: the failure kind "jam", written once
)
cd "$(dirname "$0")/.."

strict=0
if [ "$#" -gt 0 ]; then
  strict=1
  folders=("$@")
else
  folders=(core icsp estimation componentdb reduced_models model sim export cli report campaign)
fi

types=$(grep -E '^## [a-z_]+$' docs/components.md | sed 's/^## //')
found=0
for t in $types; do
  files=$(grep -rlw --include=*.cc --include=*.h "\"$t\"" "${folders[@]}" 2>/dev/null |
            grep -v "^model/src/components/${t}" |
            grep -v '^componentdb/src/default_database.cc$' || true)
  hits=""
  for f in $files; do
    if printf '%s\n' "${allowed[@]}" | grep -qx "$f:$t"; then continue; fi
    # Comments (examples in documentation) do not count.
    if grep -w "\"$t\"" "$f" | sed 's#//.*##' | grep -w "\"$t\"" | grep -qv 'kind'; then hits="$hits $f"; fi
  done
  if [ -n "$hits" ]; then
    found=1
    echo "$t:$hits"
  fi
done
if [ "$found" -eq 0 ]; then
  echo "every component type name occurs only in its own file(s) and the allowed places (${folders[*]})"
fi
if [ "$strict" -eq 1 ]; then exit "$found"; fi
exit 0
