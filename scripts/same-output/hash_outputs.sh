#!/usr/bin/env bash
# Runs `EXIDEL_BINARY triangulate` on every file of inputs/ with a fixed matrix of options and
# writes one sorted line per run to OUTFILE:
#
#   file kernel order threads incircle exitstatus sha256-of-stdout
#
# (order is "strips,strip-points=N" for the runs with an explicit --strip-points N).
# Two binaries give bit-identical triangulations on this matrix iff their OUTFILEs are equal:
#   cmp base.txt new.txt   (or: diff base.txt new.txt)
# A side file OUTFILE.log has, per run, the same key, the status, the wall time in seconds and
# the first line of stderr (failure reasons); it is for information only (times vary).
#
# Usage: hash_outputs.sh EXIDEL_BINARY OUTFILE
# Environment: JOBS (parallel runs, default 2), TIMEOUT (seconds per run, default 600;
#              a run killed by it gets status 124, which then shows up as a difference).
set -u -o pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

# ---- one run (called through xargs) -------------------------------------------------------
if [[ ${1:-} == --run-one ]]; then
    shift
    bin=$1 resdir=$2 idx=$3 file=$4 kernel=$5 order=$6 threads=$7 incircle=$8 strip=$9
    args=(triangulate -i "$here/inputs/$file" --kernel "$kernel" --threads "$threads"
          --incircle "$incircle" --format json)
    label=$order
    if [[ $strip != - ]]; then
        args+=(--order "$order" --strip-points "$strip")
        label="$order,strip-points=$strip"
    else
        args+=(--order "$order")
    fi
    errf=$resdir/$idx.err
    start=$(date +%s.%N)
    stf=$resdir/$idx.st
    hash=$( { timeout "${TIMEOUT:-600}" "$bin" "${args[@]}" 2>"$errf"; echo $? >"$stf"; } | sha256sum)
    end=$(date +%s.%N)
    status=$(cat "$stf")
    hash=${hash%% *}
    key="$file $kernel $label $threads $incircle"
    printf '%s %s %s\n' "$key" "$status" "$hash" >"$resdir/$idx.line"
    first=$(head -n 1 "$errf" | tr -d '\r')
    printf '%s %s %.3f %s\n' "$key" "$status" "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" "$first" >"$resdir/$idx.log"
    rm -f "$errf" "$stf"
    exit 0
fi

if [[ $# -ne 2 ]]; then
    echo "usage: $0 EXIDEL_BINARY OUTFILE" >&2
    exit 2
fi
bin=$(readlink -f "$1")
out=$2
[[ -x $bin ]] || { echo "$0: $1 is not an executable" >&2; exit 2; }
[[ -d $here/inputs ]] || { echo "$0: no $here/inputs; run /usr/bin/python3 $here/make_inputs.py" >&2; exit 2; }
if [[ -f $here/inputs.sha256 ]]; then
    (cd "$here" && sha256sum --quiet -c inputs.sha256) ||
        { echo "$0: inputs/ differ from inputs.sha256; regenerate them with make_inputs.py" >&2; exit 2; }
fi

SMALL=2000                       # the slow kernels and --strip-points runs: at most this many points
fast_kernels=(adaptive double long-double)
slow_kernels=(exact exact-cpp mpfr:53 mpfr:106)
# lexicographic is quadratic on these (a convex curve inserted towards its vertex, the grid)
no_lexicographic=" parabola-asc-100000.xy grid-300.xy "

resdir=$(mktemp -d "${TMPDIR:-/tmp}/exidel-verify.XXXXXX")
trap 'rm -rf "$resdir"' EXIT

# ---- the job list: idx file kernel order threads incircle strip-points, biggest inputs first
jobs=$resdir/jobs
idx=0
while read -r n file; do
    kernels=("${fast_kernels[@]}")
    (( n <= SMALL )) && kernels+=("${slow_kernels[@]}")
    for kernel in "${kernels[@]}"; do
        incircles=(determinant)
        if [[ $kernel == adaptive ]] || { (( n <= SMALL )) && [[ $kernel == double || $kernel == exact ]]; }; then
            incircles+=(cosine)
        fi
        for incircle in "${incircles[@]}"; do
            for order in auto lexicographic radial strips; do
                if [[ $order == lexicographic && $no_lexicographic == *" $file "* ]]; then continue; fi
                threadset=(1)
                [[ $order == strips || $order == auto ]] && threadset=(1 2)
                strips=(-)
                [[ $order == strips ]] && (( n <= SMALL )) && strips+=(3 64)
                for threads in "${threadset[@]}"; do
                    for strip in "${strips[@]}"; do
                        echo "$idx $file $kernel $order $threads $incircle $strip"
                        idx=$((idx + 1))
                    done
                done
            done
        done
    done
done < <(cd "$here/inputs" && for f in *.xy; do echo "$(wc -l <"$f") $f"; done | sort -k1,1nr -k2,2) >"$jobs"

total=$(wc -l <"$jobs")
echo "$0: $total runs of $bin, ${JOBS:-2} at a time" >&2
start=$(date +%s)
export TIMEOUT="${TIMEOUT:-600}"
# shellcheck disable=SC2016
xargs -P "${JOBS:-2}" -L 1 "$here/hash_outputs.sh" --run-one "$bin" "$resdir" <"$jobs"
elapsed=$(( $(date +%s) - start ))

done_count=$(find "$resdir" -name '*.line' | wc -l)
if [[ $done_count -ne $total ]]; then
    echo "$0: only $done_count of $total runs recorded" >&2
    exit 1
fi
find "$resdir" -name '*.line' -print0 | xargs -0 cat | LC_ALL=C sort >"$out.tmp" && mv "$out.tmp" "$out"
find "$resdir" -name '*.log' -print0 | xargs -0 cat | LC_ALL=C sort >"$out.log"
nonzero=$(awk '$6 != 0' "$out" | wc -l)
echo "$0: $total runs in ${elapsed}s, $nonzero exited non-zero; wrote $out (and $out.log)" >&2
