#!/bin/sh
# Prints the lexical encoder's figures on all 29 phrasing tables (tests/semantic/phrases_*.json):
# per table present precision@1 and absent rejected, then the sums over all 29.
# Usage: scripts/lexical_tables.sh [build-dir]   (default: $SP_BUILD_DIR or build)
set -e
cd "$(dirname "$0")/.."
B=${1:-${SP_BUILD_DIR:-build}}
T="$B/semantic_test_lexical"
[ -x "$T" ] || { echo "no $T: build it first (SP_BUILD_DIR=$B ./scripts/build.sh)" >&2; exit 1; }
for w in house bookstore office ward garage cafe basement classroom hotel grocery chemlab pharmacy \
         salon warehouse apartment hospital smallhouse gym museum library restaurant \
         vetclinic station cinema firestation bowling airport openoffice familyhome; do
    "$T" "$w" 2>/dev/null | grep -m1 "^$w: precision@1" || echo "$w: no figures"
done | awk '
{
    w = $1; sub(":", "", w)
    split($3, p, "/"); split($11, a, "/")
    pp += p[1]; pt += p[2]; ap += a[1]; at += a[2]
    printf "%-11s present %4d/%-4d = %.3f   absent %3d/%-3d = %.3f\n", w, p[1], p[2], p[1] / p[2], a[1], a[2], a[1] / a[2]
}
END {
    printf "%-11s present %4d/%-4d = %.3f   absent %3d/%-3d = %.3f\n", "all " NR, pp, pt, pp / pt, ap, at, ap / at
}'
