#!/usr/bin/env bash
# scripts/compare_peers.sh --equal-time: pbrt-v4 renders twice, with seeds 1 and 2, never with the seed 0
# of the references (a seed-0 render repeats the reference's first samples in every pixel), and its RMSE
# is the root mean square of the two runs'. pbrt-v4 is stood in for by illum behind pbrt-v4's command
# line; the reference is an illum render of a tiny scene of the test's own.
# Usage: compare_peers_equal_time_test.sh ILLUM REPO
source "$(dirname "${BASH_SOURCE[0]}")/test_setup.sh"

# pbrt-v4's command line (--nthreads N --spp S [--seed K] --quiet --outfile F SCENE), rendered by illum.
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
exec "$illum" render "\$scene" --spectral --threads "\$threads" \${spp:+--spp "\$spp"} --seed "\$seed" \
    -o "\$out" --quiet
SH
chmod +x "$tmp/fake-pbrt"

mkdir -p "$tmp/shared/scenes/box" "$tmp/shared/refs/spectral"
cat >"$tmp/shared/scenes/box/test.pbrt" <<'PBRT'
Integrator "path" "integer maxdepth" [ 5 ]
Sampler "independent" "integer pixelsamples" [ 16 ]
Film "rgb" "integer xresolution" [ 24 ] "integer yresolution" [ 24 ]
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
(cd "$tmp/shared/scenes/box" &&
    "$illum" render test.pbrt --spectral --spp 64 --seed 0 -o "$tmp/shared/refs/spectral/box.exr" --quiet) ||
    fail "could not render the reference"

"$repo/scripts/compare_peers.sh" --illum "$illum" --pbrt "$tmp/fake-pbrt" --shared "$tmp/shared" \
    --scenes box --runs 1 --threads 1 --equal-time 0.05 --out "$tmp/out" >"$tmp/log" 2>&1 ||
    { cat "$tmp/log" >&2; fail "compare_peers.sh failed"; }

# The equal-time renders: seeds 1 and 2, and no render with the references' seed.
grep -q -- '--seed 1 ' "$tmp/pbrt-calls" || fail "no pbrt render with seed 1"
grep -q -- '--seed 2 ' "$tmp/pbrt-calls" || fail "no pbrt render with seed 2"
! grep -q -- '--seed 0' "$tmp/pbrt-calls" || fail "a pbrt render with the reference's seed 0"

# pbrt's RMSE: the root mean square of the two runs' RMSE against the reference.
python3 - "$tmp/out" <<'PY' || fail "pbrt's RMSE is not the root mean square of its two runs'"
import csv, json, math, sys
out = sys.argv[1]
row = next(csv.DictReader(open(out + "/peers.csv")))
e = [json.load(open(f"{out}/box/pbrt-equal-time-{k}.exr.diff.json"))["rmse"]["all"] for k in (1, 2)]
expected = math.sqrt((e[0] ** 2 + e[1] ** 2) / 2)
print(f"pbrt runs {e[0]:.6g} {e[1]:.6g}: {row['pbrt_eq_rmse']} (expected {expected:.6g})")
# Both runs count: the figure lies strictly between them, where they differ by more than the CSV's 5
# significant digits can tell (they differ by a few per cent).
value = float(row["pbrt_eq_rmse"])
between = abs(e[0] - e[1]) <= 1e-3 * expected or min(e) < value < max(e)
sys.exit(not (abs(value - expected) <= 1e-4 * expected and between))
PY
echo "compare_peers.sh --equal-time: ok"
