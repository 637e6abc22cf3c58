#!/bin/sh
# srs/catalog.json is what srs/extract_catalog.py makes of the SRS, to the byte. Run from the
# repository root: catalogue_matches_srs.sh PYTHON SRS_MARKDOWN. Without the SRS (a user's clone
# has none), exits 77, which ctest reports as skipped: nothing else needs the SRS.
python=$1
srs=$2
if [ -z "$srs" ] || [ ! -f "$srs" ]; then
  echo "skipped: no SRS Markdown${srs:+ at $srs}; get GamePhysics_SRS.md from the Drasil project (https://github.com/JacquesCarette/Drasil, code/stable/gamephysics/SRS/Markdown/GamePhysics_SRS.md), put it at srs/GamePhysics_SRS.md (or pass -DGP_SRS_MARKDOWN=<path>) and configure again"
  exit 77
fi
"$python" srs/extract_catalog.py "$srs" | diff - srs/catalog.json
