#!/bin/sh
# Regenerates the albedo table of docs/verification.md ("Reflection models"): directional albedo of every model (importance mode, RGB).
I=${ILLUM:-./build/illum}
run() { "$I" brdf albedo "$@" --theta 0,30,60,80 --samples 100000 --quad 256 | sed 's/^/    /'; echo; }
run lambert
run oren-nayar -p sigma=0 -p reflectance=1
run oren-nayar -p sigma=20 -p reflectance=1
run oren-nayar -p sigma=60 -p reflectance=1
run mirror
run dielectric -p eta=1.5
run thin-dielectric -p eta=1.5
run conductor
run phong -p kd=0 -p ks=1 -p exponent=10
run phong -p kd=0 -p ks=1 -p exponent=100
run blinn-phong -p kd=0 -p ks=1 -p exponent=10
run blinn-phong -p kd=0 -p ks=1 -p exponent=100
for s in 5 20; do run torrance-sparrow -p sigma=$s -p eta=1,1,1 -p k=100; done
for m in 0.1 0.3 0.6; do run cook-torrance -p m=$m -p eta=1,1,1 -p k=100; done
for a in 0.1 0.3 0.6 1.0; do run rough-conductor -p alpha=$a -p eta=1 -p k=100; done
run rough-conductor -p alpha=0.6 -p distribution=beckmann -p eta=1 -p k=100
for a in 0.1 0.3 0.6; do run rough-dielectric -p alpha=$a -p eta=1.5; done
for a in 0.1 0.3 0.6; do run ward -p rho_d=0 -p rho_s=1 -p alpha=$a; done
run coated-diffuse -p reflectance=1
run coated-diffuse -p reflectance=1 -p roughness=0.3
run coated-conductor -p alpha=0.3
run diffuse-transmission -p reflectance=0.3 -p transmittance=0.7
run merl -p file=synthetic:0.3
run toon
