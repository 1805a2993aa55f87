#!/usr/bin/env bash
# Runs the pile pull-out with the three interface laws (inputs/pile_pullout/{rccm,coulomb,
# bonded}.yaml) and draws their curves on one figure: results/pile_laws.png (the figure of
# docs/pile_pullout.md). Usage: scripts/compare_laws.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
"$root/scripts/setup.sh"
app="${BUILD_DIR:-$root/build}/apps/pile_pullout/pile_pullout"
cd "$root"
for law in rccm coulomb bonded; do
  "$app" run "inputs/pile_pullout/$law.yaml" --quiet
done
"$root/apps/pile_pullout/plot_pullout.py" curves results/pile_laws.png \
  RCCM=results/pile_rccm Coulomb=results/pile_coulomb bonded=results/pile_bonded \
  --title "Pile pull-out (D 0.27 m, L 13 m): three interface laws"
