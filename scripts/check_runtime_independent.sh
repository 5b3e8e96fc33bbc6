#!/usr/bin/env bash
# Checks that the runtime library (libglintlab.a) references no symbol that
# only the research library (libglintlab_research.a) defines: a user linking
# glintlab::glintlab alone gets no undefined references to the paper
# experiments, validation suites or bench tables. Run by ctest
# (glintlab.runtime_without_research).
# Usage: check_runtime_independent.sh NM RUNTIME.a RESEARCH.a
set -euo pipefail
nm_tool=$1 runtime=$2 research=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Strong definitions (text, data, bss, read-only); weak and unique symbols
# (inline functions, template instances) are emitted by every user.
defined() { "$nm_tool" -P -g --defined-only "$1" | awk 'NF >= 2 && $2 ~ /^[TDBR]$/ {print $1}' | sort -u; }
undefined() { "$nm_tool" -P -u "$1" | awk 'NF >= 2 && $2 == "U" {print $1}' | sort -u; }
defined "$research" > "$tmp/research_def"
defined "$runtime" > "$tmp/runtime_def"
undefined "$runtime" > "$tmp/runtime_undef"
undefined "$research" > "$tmp/research_undef"
# The method itself: research code calls the runtime (renderers, models),
# so the same comparison the other way round must find references.
if [ -z "$(comm -12 "$tmp/research_undef" "$tmp/runtime_def")" ]; then
    echo "check_runtime_independent: found no reference from $research into $runtime;" \
         "the symbol lists are wrong (nm: $nm_tool)" >&2
    exit 2
fi
bad=$(comm -12 "$tmp/runtime_undef" "$tmp/research_def")
if [ -n "$bad" ]; then
    echo "$runtime references symbols that only $research defines:" >&2
    echo "$bad" | c++filt >&2
    exit 1
fi
echo "runtime independent of research: $(wc -l < "$tmp/research_def") research symbols," \
     "$(wc -l < "$tmp/runtime_undef") runtime undefined references, none shared"
