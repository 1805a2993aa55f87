#!/usr/bin/env bash
# Runs the pile pull-out with the RCCM interface on elastic soil and on Mohr-Coulomb soil
# (inputs/pile_pullout/{rccm,rccm_mohr_coulomb}.yaml) and draws both curves on one figure:
# results/pile_soils.png (docs/pile_pullout.md). Usage: scripts/compare_soils.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
"$root/scripts/setup.sh"
app="${BUILD_DIR:-$root/build}/apps/pile_pullout/pile_pullout"
cd "$root"
for input in rccm rccm_mohr_coulomb; do
  "$app" run "inputs/pile_pullout/$input.yaml" --quiet
done
"$root/apps/pile_pullout/plot_pullout.py" curves results/pile_soils.png \
  "elastic soil=results/pile_rccm" "Mohr-Coulomb soil=results/pile_rccm_mohr_coulomb" \
  --title "Pile pull-out (D 0.27 m, L 13 m), RCCM interface: elastic and plastic soil"
