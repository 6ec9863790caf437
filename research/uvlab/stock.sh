#!/bin/bash
# Stock Draco 1.5.5 UV cost: size(with UV) - size(--skip TEX_COORD), qp 14, qt 10/12, cl 7/10.
set -e
C=${CORPUS:-$(cd "$(dirname "$0")/../../.." && pwd)/shared/corpus}
OUT=${1:-$(dirname "$0")/out/stock.tsv}
T=$(mktemp -d)
echo -e "mesh\tqt\tcl\tbytes_with\tbytes_without\tuv_bytes" > "$OUT"
tail -n +2 $C/MANIFEST.tsv | cut -f1,2 | while IFS=$'\t' read name file; do
  for cl in 7 10; do
    draco_encoder -i $C/$file -o $T/n.drc -qp 14 -cl $cl --skip TEX_COORD >/dev/null 2>&1
    wo=$(stat -c %s $T/n.drc)
    for qt in 10 12; do
      draco_encoder -i $C/$file -o $T/w.drc -qp 14 -qt $qt -cl $cl >/dev/null 2>&1
      w=$(stat -c %s $T/w.drc)
      echo -e "$name\t$qt\t$cl\t$w\t$wo\t$((w-wo))" >> "$OUT"
    done
  done
done
rm -rf "$T"
