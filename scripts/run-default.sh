#!/usr/bin/env bash
# The main job: install what is missing, build, and run wheelwear on its built-in default case.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh build
echo
echo "== Creep forces of the reference SDEC patch (Liu, Fu & Bruni 2022, Section 5):"
echo "   a = b = 4.25 mm, psi = 0.6, pure spin phi = 1 1/m, N = 37.83 kN, mu = 0.35, G = 80 GPa"
for method in fastsim-sdec fastsim-eql fastsim-eqe fastsim-eqe-shifted linear-sdec she-sdec; do
  build/wheelwear creep --method "$method" --a 4.25e-3 --b 4.25e-3 --psi 0.6 \
    --vx 0 --vy 0 --phi 1 --N 37830 --G 80e9 --nu 0.25 --mu 0.35 --json
done
echo "   (Kalker's exact theory, CONTACT 80x80: Fx/muN = 0.4251, Fy/muN = -0.5425)"
