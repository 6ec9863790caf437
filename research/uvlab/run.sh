#!/bin/bash
# Builds uvlab and runs everything: predictor entropies (qt 10,12; qp 14; dfs + mpd order),
# stock Draco 1.5.5 UV cost, and the report tables.  Single core.
set -euo pipefail
cd "$(dirname "$0")"
export CORPUS=${CORPUS:-$(cd ../../.. && pwd)/shared/corpus}
C=$CORPUS
g++ -O2 -std=c++17 -Wall -Wno-sign-compare -o uvlab uvlab.cc
mkdir -p out
./uvlab --selftest > out/selftest.tsv
args=$(tail -n +2 $C/MANIFEST.tsv | awk -F'\t' -v C=$C '{printf "%s=%s/%s ", $1, C, $2}')
./uvlab --qp 14 --qt 10,12 $args > out/raw.tsv
grep -v '^#' out/raw.tsv > out/results.tsv
grep '^#info' out/raw.tsv | cut -f2- > out/meshinfo.tsv
grep '^#stats' out/raw.tsv | cut -f2- > out/stats.tsv
if [ ! -s out/stock.tsv ] || [ "${RERUN_STOCK:-0}" = 1 ]; then
  command -v draco_encoder >/dev/null || { echo "apt-get install -y draco first"; exit 1; }
  ./stock.sh out/stock.tsv
fi
/usr/bin/python3 report.py > out/tables.md
/usr/bin/python3 kindtable.py > out/kindtable.md
echo done: out/results.tsv out/stock.tsv out/tables.md
