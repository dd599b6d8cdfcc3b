#!/usr/bin/env bash
# Determinism across CPUs (docs/determinism.md): glibc picks FMA or plain builds of its
# transcendental functions at run time and their last bits differ, so no library calls
# them; output paths use raster/portable_math.h. The check reads the libraries' undefined
# symbols (sqrt, floor, fmod, ldexp and frexp are exact and allowed). Before the portable
# functions, scenes alone imported sincos. Usage: no_libm_transcendentals.sh LIBRARY.a ...
set -euo pipefail
names='exp|exp2|expm1|log|log2|log10|log1p|pow|sin|cos|sincos|tan|asin|acos|atan|atan2|sinh|cosh|tanh|cbrt|hypot|erf|erfc|tgamma|lgamma'
pattern="^($names)f?(@.*)?\$"
# The pattern must catch what it is for: a check that matched nothing would pass forever.
for symbol in sincos exp powf 'cos@GLIBC_2.2.5' atan2; do
    grep -qE "$pattern" <<<"$symbol" || { echo "the pattern misses: $symbol"; exit 1; }
done
grep -qE "$pattern" <<<"sqrt" && { echo "the pattern catches sqrt, which is exact"; exit 1; }
status=0
for library in "$@"; do
    undefined=$(nm -u "$library" | awk '{print $NF}' | sort -u)
    [[ -n "$undefined" ]] || { echo "$library: no undefined symbols read"; exit 1; }
    found=$(grep -E "$pattern" <<<"$undefined" || true)
    if [[ -n "$found" ]]; then
        echo "$library calls libm's run-time-dispatched functions:" $found
        status=1
    fi
done
exit "$status"
