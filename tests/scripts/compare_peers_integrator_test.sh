#!/usr/bin/env bash
# scripts/compare_peers.sh --integrator: the renderers read an altered copy of each scene's test.pbrt, in
# the output folder beside links to the scene's other files, whose Integrator directive (with its
# indented parameter lines) is replaced, or added before WorldBegin where the file has none; the shared
# folder is left as it was. Runs illum alone on two tiny scenes of its own (no peers, no ../shared).
# Usage: compare_peers_integrator_test.sh ILLUM REPO
source "$(dirname "${BASH_SOURCE[0]}")/test_setup.sh"

scene_body='
Camera "perspective" "float fov" [ 40 ]
WorldBegin
LightSource "point" "rgb I" [ 10 10 10 ] "point3 from" [ 0 2 0 ]
Include "geometry.pbrt"
'
mkdir -p "$tmp/shared/scenes/with" "$tmp/shared/scenes/without"
for scene in with without; do
    echo 'Shape "sphere" "float radius" [ 1 ]' >"$tmp/shared/scenes/$scene/geometry.pbrt"
done
cat >"$tmp/shared/scenes/with/test.pbrt" <<PBRT
# a comment
Integrator "path"
    "integer maxdepth" [ 65 ]
    "bool regularize" [ false ]
Film "rgb" "integer xresolution" [ 16 ] "integer yresolution" [ 12 ]
$scene_body
PBRT
cat >"$tmp/shared/scenes/without/test.pbrt" <<PBRT
Film "rgb" "integer xresolution" [ 16 ] "integer yresolution" [ 12 ]
$scene_body
PBRT
cp -r "$tmp/shared" "$tmp/shared.before"

"$repo/scripts/compare_peers.sh" --illum "$illum" --shared "$tmp/shared" --quick --scenes "with without" \
    --integrator 'direct "integer maxdepth" [ 2 ]' --out "$tmp/out" >"$tmp/log" 2>&1 ||
    { cat "$tmp/log" >&2; fail "compare_peers.sh failed"; }

for scene in with without; do
    copy="$tmp/out/$scene/scene/test.pbrt"
    [[ -f "$copy" ]] || fail "$scene: no altered copy"
    [[ "$(grep -c '^Integrator' "$copy")" == 1 ]] || fail "$scene: not one Integrator directive"
    grep -qx 'Integrator "direct" "integer maxdepth" \[ 2 \]' "$copy" || fail "$scene: the new directive"
    [[ -L "$tmp/out/$scene/scene/geometry.pbrt" ]] || fail "$scene: the scene's other files are not linked"
    grep -q "rendering $scene (16 x 12, 4 spp, direct)" "$tmp/log" || fail "$scene: not rendered as direct"
    [[ -f "$tmp/out/$scene/illum.exr" ]] || fail "$scene: no image"
done
# The old directive's parameter lines went with it; the rest of the file is unchanged.
! grep -q 'maxdepth" \[ 65 \]\|regularize' "$tmp/out/with/scene/test.pbrt" || fail "old parameters left"
grep -q '^# a comment' "$tmp/out/with/scene/test.pbrt" || fail "the rest of the file changed"
# Added before WorldBegin where there was none.
[[ "$(grep -n -m1 '^Integrator' "$tmp/out/without/scene/test.pbrt" | cut -d: -f1)" -lt \
   "$(grep -n -m1 '^WorldBegin' "$tmp/out/without/scene/test.pbrt" | cut -d: -f1)" ]] ||
    fail "the directive is not before WorldBegin"
diff -r "$tmp/shared" "$tmp/shared.before" >/dev/null || fail "the shared folder changed"
grep -q '^| with | 16x12 | 4 |' "$tmp/log" || fail "no table row"

# A directive that is not one is refused before anything runs.
if "$repo/scripts/compare_peers.sh" --illum "$illum" --shared "$tmp/shared" --quick --scenes with \
    --integrator '[ 2 ]' --out "$tmp/out2" >"$tmp/log2" 2>&1; then
    fail "a bad --integrator was accepted"
fi
grep -q "integrator takes" "$tmp/log2" || fail "no message for a bad --integrator"
echo "compare_peers.sh --integrator: ok"
