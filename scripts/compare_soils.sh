#!/usr/bin/env bash
# Runs the pile pull-out with the rate-independent RCCM interface, traced through its
# snap-back, on elastic soil and on Mohr-Coulomb soil
# (inputs/pile_pullout/{rccm_traced,rccm_mohr_coulomb}.yaml) and draws both curves on one figure:
# results/pile_soils.png (docs/pile_pullout.md). Usage: scripts/compare_soils.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
"$root/scripts/setup.sh"
app="${BUILD_DIR:-$root/build}/apps/pile_pullout/pile_pullout"
cd "$root"
for input in rccm_traced rccm_mohr_coulomb; do
  "$app" run "inputs/pile_pullout/$input.yaml" --quiet
done
"$root/apps/pile_pullout/plot_pullout.py" curves results/pile_soils.png \
  "elastic soil=results/pile_rccm_traced" "Mohr-Coulomb soil=results/pile_rccm_mohr_coulomb" \
  --title "Pile pull-out, RCCM (alpha = 0) traced: elastic and Mohr-Coulomb soil"
