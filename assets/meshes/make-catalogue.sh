#!/bin/sh
# Regenerates the phantom catalogue (assets/meshes); run from the repository top.
set -e
B=${COILSIM:-build/src/app/coilsim}
D=assets/meshes
$B phantom --type sidewall    --sac-mm 5  --dome-to-neck 2   --resolution-mm 0.55  --out $D/sidewall-5mm.stl
$B phantom --type sidewall    --sac-mm 7  --dome-to-neck 2   --resolution-mm 0.6   --out $D/sidewall-7mm.stl
$B phantom --type sidewall    --sac-mm 10 --neck-mm 4        --resolution-mm 0.65 --out $D/sidewall-10mm.stl
$B phantom --type sidewall    --sac-mm 7  --neck-mm 5.5      --resolution-mm 0.6   --out $D/sidewall-7mm-wide-neck.stl
$B phantom --type sidewall    --sac-mm 7  --dome-to-neck 2 --lobes 3 --resolution-mm 0.55 --out $D/multilobe-7mm.stl
$B phantom --type curved      --sac-mm 7  --dome-to-neck 2   --resolution-mm 0.65 --out $D/curved-7mm.stl
$B phantom --type bifurcation --sac-mm 7  --neck-mm 4        --resolution-mm 0.6  --out $D/bifurcation-7mm.stl
