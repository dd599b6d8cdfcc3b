#!/usr/bin/env bash
# The determinism contract (docs/determinism.md): no fused multiply-add and no approximate
# reciprocal or reciprocal square root anywhere in the libraries' machine code, in any of the
# per-ISA units (the AVX-512 ones could fuse if contraction were ever allowed), whatever the
# compiler chose. Usage: no_fused_instructions.sh LIBRARY.a ...
set -euo pipefail
pattern='[[:space:]](vfn?m(add|sub)[0-9a-z]*|v?rcp[0-9a-z]*|v?rsqrt[0-9a-z]*)[[:space:]]'
# The pattern must catch what it is for: a check that matched nothing would pass forever.
for line in $'  10:\tvfmadd231ps %zmm1,%zmm2,%zmm3' $'  10:\tvrcp14ps %zmm1,%zmm2' \
            $'  10:\trsqrtss %xmm1,%xmm2' $'  10:\tvfnmsub213sd %xmm1,%xmm2,%xmm3'; do
    grep -qE "$pattern" <<<"$line" || { echo "the pattern misses: $line"; exit 1; }
done
status=0
for library in "$@"; do
    listing=$(objdump -d --no-show-raw-insn "$library")
    instructions=$(grep -cE $'^ +[0-9a-f]+:\t' <<<"$listing" || true)
    if (( instructions < 1000 )); then echo "$library: only $instructions instructions disassembled"; exit 1; fi
    found=$(grep -E "$pattern" <<<"$listing" | head -5 || true)
    if [[ -n "$found" ]]; then
        echo "$library holds fused or approximate instructions:"
        echo "$found"
        status=1
    fi
done
exit "$status"
