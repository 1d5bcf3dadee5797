#!/usr/bin/env bash
# scripts/compare_peers.sh --equal-time: pbrt-v4 renders with seeds 1 and 2, never with the seed 0 of the
# references, and the two runs measure the reference's own noise, which is taken out of both renderers'
# errors ("converged" columns). pbrt-v4 is stood in for by illum behind pbrt-v4's command line, and the
# reference is an illum render of a tiny scene at 16 spp (noisy on purpose, so its noise is
# measurable), which must come out as the variance of two more 16-spp renders.
# Usage: compare_peers_equal_time_test.sh ILLUM REPO
set -euo pipefail
illum="$1"
repo="$2"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

fail() {
    echo "FAIL: $*" >&2
    exit 1
}

# pbrt-v4's command line (--nthreads N --spp S [--seed K] --quiet --outfile F SCENE), rendered by illum
# with seed K + 7: the reference is "pbrt's" seed 0, illum's seed 7, so that illum's own equal-time render
# (seed 0) shares nothing with it, as with the real references.
cat >"$tmp/fake-pbrt" <<SH
#!/usr/bin/env bash
echo "\$*" >>"$tmp/pbrt-calls"
threads=1 spp="" seed=0 out="" scene=""
while [[ \$# -gt 0 ]]; do
    case "\$1" in
        --nthreads) threads="\$2"; shift 2 ;;
        --spp) spp="\$2"; shift 2 ;;
        --seed) seed="\$2"; shift 2 ;;
        --outfile) out="\$2"; shift 2 ;;
        --quiet) shift ;;
        *) scene="\$1"; shift ;;
    esac
done
[[ -f "\$scene" ]] || { echo "no scene \$scene" >&2; exit 1; }
exec "$illum" render "\$scene" --spectral --threads "\$threads" \${spp:+--spp "\$spp"} --seed "\$((seed + 7))" \
    -o "\$out" --quiet
SH
chmod +x "$tmp/fake-pbrt"

mkdir -p "$tmp/shared/scenes/box" "$tmp/shared/refs/spectral"
cat >"$tmp/shared/scenes/box/test.pbrt" <<'PBRT'
Integrator "path" "integer maxdepth" [ 5 ]
Sampler "independent" "integer pixelsamples" [ 16 ]
Film "rgb" "integer xresolution" [ 64 ] "integer yresolution" [ 64 ]
LookAt 0 1 4  0 0.5 0  0 1 0
Camera "perspective" "float fov" [ 45 ]
WorldBegin
LightSource "infinite" "rgb L" [ 1 1 1 ]
Material "diffuse" "rgb reflectance" [ 0.6 0.5 0.4 ]
Translate 0 0.5 0
Shape "sphere" "float radius" [ 0.5 ]
Shape "trianglemesh" "integer indices" [ 0 1 2 0 2 3 ]
    "point3 P" [ -5 -0.5 -5  5 -0.5 -5  5 -0.5 5  -5 -0.5 5 ]
PBRT
(cd "$tmp/shared/scenes/box" && "$illum" render test.pbrt --spectral --spp 16 --seed 7 \
    -o "$tmp/shared/refs/spectral/box.exr" --quiet) || fail "could not render the reference"

"$repo/scripts/compare_peers.sh" --illum "$illum" --pbrt "$tmp/fake-pbrt" --shared "$tmp/shared" \
    --scenes box --runs 1 --threads 1 --equal-time 0.05 --out "$tmp/out" >"$tmp/log" 2>&1 ||
    { cat "$tmp/log" >&2; fail "compare_peers.sh failed"; }

# The equal-time renders: seeds 1 and 2, and no render with the references' seed.
grep -q -- '--seed 1 ' "$tmp/pbrt-calls" || fail "no pbrt render with seed 1"
grep -q -- '--seed 2 ' "$tmp/pbrt-calls" || fail "no pbrt render with seed 2"
! grep -q -- '--seed 0' "$tmp/pbrt-calls" || fail "a pbrt render with the reference's seed 0"

# The CSV's columns by name.
field() {
    python3 - "$tmp/out/peers.csv" "$1" <<'PY'
import csv, sys
row = next(csv.DictReader(open(sys.argv[1])))
print(row[sys.argv[2]])
PY
}
noise="$(field reference_noise_rmse)"
pbrt_conv="$(field pbrt_eq_rmse_converged)"
pbrt_spp="$(field pbrt_eq_spp)"
illum_rmse="$(field illum_eq_rmse)"
illum_conv="$(field illum_eq_rmse_converged)"
echo "reference noise $noise, pbrt converged $pbrt_conv at $pbrt_spp spp, illum $illum_rmse -> $illum_conv"
awk -v n="$noise" -v p="$pbrt_conv" -v i="$illum_rmse" -v c="$illum_conv" 'BEGIN {
    e = c * c - (i * i - n * n); exit !(n > 0 && p > 0 && c < i && e < 1e-3 * i * i && e > -1e-3 * i * i) }' ||
    fail "the converged figures do not follow from the reference's noise"
# The reference's noise is that of a 16-spp render: two more of them (seeds 3 and 4) differ by d with
# d^2 / 2 their variance. The scene is lit by a uniform environment, so that no firefly decides either
# figure: measured, the two agree within 7%. A wrong formula (d^2 in place of d^2 / 2) gives 0.11.
for seed in 3 4; do
    (cd "$tmp/shared/scenes/box" && "$illum" render test.pbrt --spectral --spp 16 --seed "$seed" \
        -o "$tmp/r$seed.exr" --quiet) || fail "could not render seed $seed"
done
d="$("$illum" diff --json "$tmp/r3.exr" "$tmp/r4.exr" | python3 -c 'import json, sys; print(json.load(sys.stdin)["rmse"]["all"])')"
awk -v n="$noise" -v d="$d" 'BEGIN {
    r = n * n / (d * d / 2); print "reference variance, measured / from two 16-spp renders: " r
    exit !(r > 0.5 && r < 2) }' || fail "the reference's noise is not that of its 16 spp"
echo "compare_peers.sh --equal-time: ok"
