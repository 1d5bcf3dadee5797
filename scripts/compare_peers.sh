#!/usr/bin/env bash
# Side-by-side timing of illum against its peers (issue 15): pbrt-v4 on every shared scene, and Cycles
# (Blender) on the Cornell box. See the usage text below and docs/performance.md, "Comparing with the
# peers". Nothing is written into the repository or the shared folder: every image, log and the CSV go
# to the --out directory.
set -euo pipefail

script_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo_dir="$(cd "$script_dir/.." && pwd)"

usage() {
    cat <<'EOF'
Usage: scripts/compare_peers.sh [options]

Times illum against pbrt-v4 (and Cycles, on the Cornell box) on the shared scenes and prints a Markdown
table of the ratios; the same table goes to peers.csv in the output folder.

Each renderer runs as a whole process from the scene's own folder (scenes include relative files), N
times; the figure is the median wall time of the N runs. illum renders with --spectral, because pbrt-v4
renders spectrally. Samples per second are width x height x spp / wall time (for SPPM, spp is the
number of iterations). Peak RSS comes from /usr/bin/time.

Options:
  --pbrt PATH          pbrt-v4 executable (built outside the repository; optional)
  --blender PATH       Blender executable, for Cycles on the Cornell box (optional)
  --illum PATH         illum executable (default: build/illum in the repository)
  --shared DIR         shared scenes and references (default: $ILLUM_SHARED_DIR, else ../shared
                       beside the repository)
  --threads N          render threads of every renderer (default 2)
  --runs N             whole-process runs per renderer and scene; the median is reported (default 5)
  --scenes "a b"       scene folders of DIR/scenes (default: every folder holding a test.pbrt)
  --spp N              samples per pixel of every scene and renderer (default: each scene's own)
  --integrator "D"     render every scene with this Integrator directive in place of its own, e.g.
                       'bdpt "integer maxdepth" [ 5 ]' (both renderers read the same altered copy of
                       test.pbrt, made in the output folder beside links to the scene's files; Cycles,
                       a path tracer, is left out)
  --equal-time S       also render each scene for about S seconds with each renderer (illum --time S;
                       pbrt-v4 at the spp its timed runs predict for the wall time illum's run took)
                       and print the RMSE of each against DIR/refs/spectral/<scene>.exr. pbrt-v4
                       renders twice, with seeds 1 and 2, and its RMSE is the root mean square of the
                       two: the references are its renders with its default seed 0, whose first
                       samples in every pixel a seed-0 render would repeat (its error against the
                       reference then comes out low)
  --adaptive           illum's equal-time renders use adaptive sampling (--adaptive) where the scene's
                       integrator's samples start in a pixel (path, volpath, bdpt); the others as they are
  --quick              1 run at 4 spp: checks the script, measures nothing
  --out DIR            where images, logs and peers.csv go (default: a new folder under /tmp)
  -h, --help           this text

Ratios are pbrt/illum (above 1: illum is faster, or has the lower error) and Cycles/illum.
Run it on an idle machine: the figures are only as quiet as the machine.
EOF
}

die() {
    echo "compare_peers.sh: $*" >&2
    exit 1
}

# ---------------------------------------------------------------------------------------------------
# Options.

pbrt=""
blender=""
illum="$repo_dir/build/illum"
shared="${ILLUM_SHARED_DIR:-$repo_dir/../shared}"
threads=2
runs=5
scenes=""
spp_override=""
equal_time=""
out_dir=""
integrator_override=""
adaptive=0

need_value() {
    [[ $# -ge 2 && -n "$2" ]] || die "$1 needs a value (see --help)"
}

while [[ $# -gt 0 ]]; do
    case "$1" in
        --pbrt) need_value "$@"; pbrt="$2"; shift 2 ;;
        --blender) need_value "$@"; blender="$2"; shift 2 ;;
        --illum) need_value "$@"; illum="$2"; shift 2 ;;
        --shared) need_value "$@"; shared="$2"; shift 2 ;;
        --threads) need_value "$@"; threads="$2"; shift 2 ;;
        --runs) need_value "$@"; runs="$2"; shift 2 ;;
        --scenes) need_value "$@"; scenes="$2"; shift 2 ;;
        --spp) need_value "$@"; spp_override="$2"; shift 2 ;;
        --equal-time) need_value "$@"; equal_time="$2"; shift 2 ;;
        --integrator) need_value "$@"; integrator_override="$2"; shift 2 ;;
        --adaptive) adaptive=1; shift ;;
        --quick) runs=1; spp_override=4; shift ;;
        --out) need_value "$@"; out_dir="$2"; shift 2 ;;
        -h | --help) usage; exit 0 ;;
        *) die "unknown argument '$1' (see --help)" ;;
    esac
done

positive_integer() {
    [[ "$2" =~ ^[1-9][0-9]*$ ]] || die "$1 must be a positive integer, not '$2'"
}
positive_integer --threads "$threads"
positive_integer --runs "$runs"
[[ -z "$spp_override" ]] || positive_integer --spp "$spp_override"
if [[ -n "$equal_time" ]]; then
    [[ "$equal_time" =~ ^[0-9]*\.?[0-9]+$ ]] || die "--equal-time takes seconds, not '$equal_time'"
fi
if [[ -n "$integrator_override" ]]; then
    [[ "$integrator_override" =~ ^\"?[a-z]+ ]] ||
        die "--integrator takes a directive's name and parameters, e.g. 'bdpt \"integer maxdepth\" [ 5 ]'"
    [[ -z "$blender" ]] || echo "compare_peers.sh: --integrator: Cycles is left out" >&2
    blender=""
fi

# Paths become absolute: every renderer runs from its scene's folder.
absolute_executable() {
    local name="$1" path="$2" resolved
    if [[ "$path" != */* ]]; then
        resolved="$(command -v "$path" || true)"
        [[ -n "$resolved" ]] || die "$name: '$path' is not on the PATH"
        path="$resolved"
    fi
    [[ -x "$path" && ! -d "$path" ]] || die "$name: '$path' is not an executable file"
    echo "$(cd "$(dirname "$path")" && pwd)/$(basename "$path")"
}
illum="$(absolute_executable --illum "$illum")"
[[ -z "$pbrt" ]] || pbrt="$(absolute_executable --pbrt "$pbrt")"
[[ -z "$blender" ]] || blender="$(absolute_executable --blender "$blender")"
[[ -d "$shared/scenes" ]] || die "no scenes folder in '$shared' (set --shared or ILLUM_SHARED_DIR)"
shared="$(cd "$shared" && pwd)"

command -v python3 >/dev/null || die "python3 is needed (to read the scene headers and illum's JSON)"

if [[ -z "$scenes" ]]; then
    for folder in "$shared"/scenes/*/; do
        if [[ -f "$folder/test.pbrt" ]]; then scenes+="$(basename "$folder") "; fi
    done
fi
for scene in $scenes; do
    [[ -f "$shared/scenes/$scene/test.pbrt" ]] || die "no $shared/scenes/$scene/test.pbrt"
done
[[ -n "${scenes// /}" ]] || die "no scenes to render"

if [[ -z "$out_dir" ]]; then
    out_dir="$(mktemp -d /tmp/compare_peers.XXXXXX)"
else
    # Checked before it is created, so a wrong --out leaves nothing behind in the repository.
    out_dir="$(realpath -m "$out_dir")"
    case "$out_dir/" in
        "$(realpath "$repo_dir")"/* | "$(realpath "$shared")"/*)
            die "--out must lie outside the repository and the shared folder" ;;
    esac
    mkdir -p "$out_dir"
fi

# GNU time gives the peak RSS; without it the RSS columns stay empty (the wall time is bash's anyway).
gnu_time=/usr/bin/time
if ! "$gnu_time" -f "%M" -o /dev/null true 2>/dev/null; then
    echo "compare_peers.sh: /usr/bin/time (the Debian package 'time') is missing: timing with bash" \
         "alone, without peak RSS (apt-get install time to have it)" >&2
    gnu_time=""
fi

# ---------------------------------------------------------------------------------------------------
# Helpers.

# Prints "width height spp integrator" of a pbrt-v4 file, with pbrt-v4's defaults for what it omits
# (1280x720, 16 spp, volpath). Only the file itself is read: the shared test.pbrt files keep their Film,
# Sampler and Integrator there.
scene_header() {
    python3 - "$1" "$script_dir" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from pbrt_tokens import tokenize
tokens = tokenize(open(sys.argv[1]).read())
# Split into directives (capitalised bare words) and their arguments.
statements, current = [], None
for token in tokens:
    if token[0].isalpha() and token[0].isupper():
        current = [token, []]
        statements.append(current)
    elif current is not None:
        current[1].append(token)
def first_value(args, name):
    for i, token in enumerate(args):
        if token.startswith('"') and token.strip('"').split()[-1:] == [name]:
            value = args[i + 1] if args[i + 1] != '[' else args[i + 2]
            return value.strip('"')
    return None
width, height, spp, integrator = 1280, 720, 16, "volpath"
for directive, args in statements:
    if directive == "Film":
        width = int(first_value(args, "xresolution") or width)
        height = int(first_value(args, "yresolution") or height)
    elif directive == "Sampler":
        spp = int(first_value(args, "pixelsamples") or spp)
    elif directive == "Integrator":
        integrator = args[0].strip('"')
    elif directive == "WorldBegin":
        break
print(width, height, spp, integrator)
PY
}

# The scene folder to render: the shared one, or with --integrator a folder in the output holding links
# to every file of the shared one and a copy of test.pbrt whose Integrator directive (its line and the
# indented parameter lines after it) is replaced, or added before WorldBegin where it has none.
scene_folder() {
    local scene="$1" shared_folder="$shared/scenes/$1"
    if [[ -z "$integrator_override" ]]; then
        echo "$shared_folder"
        return
    fi
    local variant="$out_dir/$scene/scene"
    mkdir -p "$variant"
    local entry
    for entry in "$shared_folder"/*; do
        [[ "$(basename "$entry")" == test.pbrt ]] || ln -sfn "$entry" "$variant/$(basename "$entry")"
    done
    python3 - "$shared_folder/test.pbrt" "$variant/test.pbrt" "$integrator_override" <<'PY' ||
import re, sys
text = open(sys.argv[1]).read()
directive = "Integrator " + re.sub(r'^(\w+)', r'"\1"', sys.argv[3].strip()) + "\n"
pattern = re.compile(r'^Integrator\b[^\n]*\n(?:[ \t]+"[^\n]*\n)*', re.M)
if pattern.search(text):
    text = pattern.sub(lambda m: directive, text, count=1)
elif re.search(r'^WorldBegin\b', text, re.M):
    text = re.sub(r'^WorldBegin\b', lambda m: directive + "\n" + m.group(0), text, count=1, flags=re.M)
else:
    sys.exit("no Integrator directive and no WorldBegin in " + sys.argv[1])
open(sys.argv[2], "w").write(text)
PY
        die "could not write $variant/test.pbrt"
    echo "$variant"
}

# One field of a JSON file, e.g. json_field FILE rmse all; "" when the file or the field is missing
# (illum diff gives no RMSE when the sizes differ), so one missing figure does not end the comparison.
json_field() {
    python3 - "$@" <<'PY'
import json, sys
try:
    value = json.load(open(sys.argv[1]))
    for key in sys.argv[2:]:
        value = value[key]
except (OSError, ValueError, KeyError, TypeError):
    value = ""
print(value)
PY
}

# RMSE (all channels) of an image against a reference, by illum diff, and the same with the 0.1% of the
# pixels with the largest errors left out (illum diff's trimmed RMSE: one firefly, a rare path to a
# sub-pixel emitter, decides the plain figure by luck); "" for a figure that cannot be had.
rmse_against() {
    local image="$1" reference="$2" report="$1.diff.json"
    if "$illum" diff --json "$image" "$reference" >"$report" 2>&1; then
        echo "$(json_field "$report" rmse all) $(json_field "$report" rmse_trimmed all)"
    else
        echo "compare_peers.sh: illum diff $image $reference failed (see $report)" >&2
        echo " "
    fi
}

# Arithmetic on decimals (bash has integers only): calc 'a1 / a2' X Y. Prints "" when an operand is
# empty (a renderer that did not run), so a missing figure stays missing instead of failing the script.
calc() {
    local expression="$1"
    shift
    local variables=() index=1 operand
    for operand in "$@"; do
        [[ -n "$operand" ]] || { echo ""; return; }
        variables+=(-v "a$index=$operand")
        index=$((index + 1))
    done
    awk "${variables[@]}" "BEGIN { printf \"%.10g\\n\", ($expression) }"
}

# Median of the numbers given as arguments.
# Empty arguments (no peak RSS without GNU time) are skipped; with none left the median is "".
median() {
    printf '%s\n' "$@" | sort -g | awk 'NF { v[++n] = $1 } END {
        if (n == 0) print ""
        else if (n % 2) print v[(n + 1) / 2]
        else printf "%.10g\n", (v[n / 2] + v[n / 2 + 1]) / 2 }'
}

# Runs a command in a folder, its output to a log; sets run_seconds (wall) and run_rss_kb (peak RSS,
# empty without GNU time). Returns the command's status. The wall time is taken by bash around the
# process even when GNU time runs it, because GNU time's %e has only centiseconds.
timed_run() {
    local folder="$1" log="$2"
    shift 2
    run_seconds=""
    run_rss_kb=""
    local status=0 start end
    local measure="$log.time"
    local wrapper=()
    [[ -z "$gnu_time" ]] || wrapper=("$gnu_time" -f "%M" -o "$measure")
    start="$(date +%s.%N)"
    (cd "$folder" && "${wrapper[@]}" "$@") >"$log" 2>&1 || status=$?
    end="$(date +%s.%N)"
    if [[ $status -ne 0 ]]; then
        echo "compare_peers.sh: failed (status $status): $* (in $folder); its log, $log, ends:" >&2
        tail -n 5 "$log" >&2 || true
        return "$status"
    fi
    run_seconds="$(calc 'a2 - a1' "$start" "$end")"
    # GNU time writes a "Command exited with ..." line before its figures on failures only.
    [[ -z "$gnu_time" ]] || run_rss_kb="$(tail -n 1 "$measure")"
}

# Formats: seconds to 3 decimals, KiB as MiB, rates in millions, ratios to 2 decimals; "" stays "".
fmt() {
    local format="$1" value="$2"
    [[ -n "$value" ]] || { echo ""; return; }
    awk -v v="$value" -v f="$format" 'BEGIN { printf f "\n", v }'
}

# Blender's own render time, from its final "Time: mm:ss.ss (Saving: ...)" line (hours appear as
# hh:mm:ss.ss on long renders); falls back to the "render seconds" the Cycles script prints.
blender_render_seconds() {
    local log="$1" stamp
    stamp="$(grep -oE '^ ?Time: [0-9:.]+ \(Saving' "$log" | tail -n 1 |
        grep -oE '[0-9]+(:[0-9]+)*(\.[0-9]+)?' | head -n 1 || true)"
    if [[ -n "$stamp" ]]; then
        awk -v t="$stamp" 'BEGIN { n = split(t, p, ":"); s = 0
            for (i = 1; i <= n; i++) s = s * 60 + p[i]
            print s }'
    else
        grep -oE 'cycles_cornell: render seconds [0-9.]+' "$log" | awk '{ print $4 }' | tail -n 1
    fi
}

# ---------------------------------------------------------------------------------------------------
# Versions and the machine.

illum_version="$("$illum" --version 2>/dev/null | head -n 1 || true)"
pbrt_version=""
if [[ -n "$pbrt" ]]; then
    # pbrt-v4 has no --version; it prints its banner before reading the scene, so a missing file
    # gives the banner and an error without rendering anything.
    pbrt_version="$("$pbrt" --nthreads 1 "$out_dir/no-such-scene.pbrt" 2>/dev/null |
        grep -m 1 'pbrt version' || true)"
    pbrt_version="${pbrt_version:-pbrt-v4 (no version printed)}"
fi
blender_version=""
[[ -z "$blender" ]] || blender_version="$("$blender" --version 2>/dev/null | head -n 1 || true)"

echo "# illum and its peers"
echo
echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC'); machine: $(uname -m), $(nproc) cores; threads: $threads;" \
     "runs: $runs (median of whole processes)${spp_override:+; spp: $spp_override for every scene}"
echo "- illum: $illum_version ($illum), --spectral"
[[ -z "$integrator_override" ]] || echo "- every scene with: Integrator $integrator_override"
[[ $adaptive -eq 0 || -z "$equal_time" ]] || echo "- illum's equal-time renders of path, volpath and bdpt scenes: --adaptive"
[[ -z "$pbrt" ]] || echo "- pbrt-v4: $pbrt_version ($pbrt)"
[[ -z "$blender" ]] || echo "- Cycles: $blender_version ($blender), CPU"
echo "- output: $out_dir"
[[ -n "$gnu_time" ]] || echo "- /usr/bin/time missing: no peak RSS"
echo

# ---------------------------------------------------------------------------------------------------
# The runs.

csv="$out_dir/peers.csv"
columns=(scene resolution spp illum_s illum_rss_mib illum_msamples_per_s pbrt_s pbrt_rss_mib
         pbrt_msamples_per_s pbrt_over_illum)
if [[ -n "$equal_time" ]]; then
    columns+=(equal_time_s illum_eq_spp illum_eq_s illum_eq_rmse pbrt_eq_spp pbrt_eq_s pbrt_eq_rmse
              rmse_pbrt_over_illum illum_eq_rmse_trimmed pbrt_eq_rmse_trimmed rmse_trimmed_pbrt_over_illum)
fi
(IFS=,; echo "${columns[*]}") >"$csv"

titles=("scene" "resolution" "spp" "illum s" "illum RSS MiB" "illum Msamples/s" "pbrt s" "pbrt RSS MiB"
        "pbrt Msamples/s" "pbrt/illum")
if [[ -n "$equal_time" ]]; then
    titles+=("equal time s" "illum spp" "illum s" "illum RMSE" "pbrt spp" "pbrt s" "pbrt RMSE"
             "RMSE pbrt/illum" "illum RMSE trimmed" "pbrt RMSE trimmed" "trimmed pbrt/illum")
fi
cycles_columns=(scene resolution spp illum_rgb_s illum_rgb_render_s illum_rgb_rss_mib cycles_s cycles_render_s
                cycles_rss_mib cycles_over_illum cycles_over_illum_render)
cycles_titles=("scene" "resolution" "spp" "illum RGB s" "illum render s" "illum RSS MiB" "Cycles s"
               "Cycles render s" "Cycles RSS MiB" "Cycles/illum" "Cycles/illum render")

# Rows are kept as cells joined by the ASCII unit separator, which no cell holds (a comma or a tab could
# appear in a path or collapse empty cells); empty cells are a peer that was not given or failed.
separator=$'\x1f'
join_cells() {
    local IFS="$separator"
    echo "$*"
}
rows=()
cycles_row=""

for scene in $scenes; do
    scene_out="$out_dir/$scene"
    mkdir -p "$scene_out"
    folder="$(scene_folder "$scene")"
    header="$(scene_header "$folder/test.pbrt")" || die "could not read $folder/test.pbrt"
    read -r width height scene_spp integrator <<<"$header"
    spp="${spp_override:-$scene_spp}"
    spp_args=()
    [[ -z "$spp_override" ]] || spp_args=(--spp "$spp_override")
    echo "rendering $scene ($width x $height, $spp spp, $integrator) ..." >&2

    # The two renderers alternate run by run, so a slow drift of the machine touches both alike.
    illum_times=() illum_rss=() pbrt_times=() pbrt_rss=()
    illum_ok=1 pbrt_ok=1
    [[ -n "$pbrt" ]] || pbrt_ok=0
    for ((run = 1; run <= runs; run++)); do
        if [[ $pbrt_ok -eq 1 ]]; then
            if timed_run "$folder" "$scene_out/pbrt.$run.log" "$pbrt" --nthreads "$threads" \
                "${spp_args[@]}" --quiet --outfile "$scene_out/pbrt.exr" test.pbrt; then
                pbrt_times+=("$run_seconds")
                pbrt_rss+=("$run_rss_kb")
            else
                pbrt_ok=0
            fi
        fi
        if [[ $illum_ok -eq 1 ]]; then
            if timed_run "$folder" "$scene_out/illum.$run.log" "$illum" render test.pbrt \
                --threads "$threads" --spectral "${spp_args[@]}" -o "$scene_out/illum.exr" --quiet; then
                illum_times+=("$run_seconds")
                illum_rss+=("$run_rss_kb")
            else
                illum_ok=0
            fi
        fi
    done
    pixels_samples=$((width * height * spp))
    illum_s="" illum_mib="" illum_rate="" pbrt_s="" pbrt_mib="" pbrt_rate=""
    if [[ $illum_ok -eq 1 ]]; then
        illum_s="$(median "${illum_times[@]}")"
        illum_mib="$(calc 'a1 / 1024' "$(median "${illum_rss[@]}")")"
        illum_rate="$(calc 'a1 / a2 / 1e6' "$pixels_samples" "$illum_s")"
    fi
    if [[ $pbrt_ok -eq 1 ]]; then
        pbrt_s="$(median "${pbrt_times[@]}")"
        pbrt_mib="$(calc 'a1 / 1024' "$(median "${pbrt_rss[@]}")")"
        pbrt_rate="$(calc 'a1 / a2 / 1e6' "$pixels_samples" "$pbrt_s")"
    fi
    ratio="$(calc 'a1 / a2' "$pbrt_s" "$illum_s")"
    row=("$scene" "${width}x$height" "$spp" "$(fmt %.3f "$illum_s")" "$(fmt %.1f "$illum_mib")"
         "$(fmt %.3f "$illum_rate")" "$(fmt %.3f "$pbrt_s")" "$(fmt %.1f "$pbrt_mib")"
         "$(fmt %.3f "$pbrt_rate")" "$(fmt %.2f "$ratio")")

    # Equal time: illum for S seconds of rendering (--time), then pbrt-v4 at the spp its timed runs
    # predict for the wall time illum's whole process took (S plus illum's start-up and writing), so that
    # both processes get the same wall clock; the prediction scales pbrt's whole-process median, start-up
    # included, so its run may come out a little shorter. The table shows both actual times. Each image
    # is compared with the spectral reference.
    if [[ -n "$equal_time" ]]; then
        reference="$shared/refs/spectral/$scene.exr"
        eq_illum_spp="" eq_illum_s="" eq_illum_rmse="" eq_pbrt_spp="" eq_pbrt_s="" eq_pbrt_rmse=""
        eq_illum_trim="" eq_pbrt_trim=""
        eq_illum_args=()
        if [[ $adaptive -eq 1 && ( "$integrator" == path || "$integrator" == volpath || "$integrator" == bdpt ) ]]; then
            eq_illum_args=(--adaptive)
        fi
        if [[ $illum_ok -eq 1 ]] && timed_run "$folder" "$scene_out/illum-equal-time.log" "$illum" render \
            test.pbrt --threads "$threads" --spectral --time "$equal_time" "${eq_illum_args[@]}" \
            -o "$scene_out/illum-equal-time.exr" --quiet --stats "$scene_out/illum-equal-time.json"; then
            eq_illum_spp="$(json_field "$scene_out/illum-equal-time.json" spp)"
            eq_illum_s="$run_seconds"
            [[ ! -f "$reference" ]] ||
                read -r eq_illum_rmse eq_illum_trim \
                    <<<"$(rmse_against "$scene_out/illum-equal-time.exr" "$reference")"
        fi
        # pbrt-v4 renders twice, with seeds 1 and 2 (the references are its renders with seed 0; see the
        # usage text). Its RMSE is the root mean square of the two runs' (plain and trimmed alike). No seed
        # changes the pixel positions of pbrt-v4's "sobol" sampler (SobolSampler::GetPixel2D takes them
        # unscrambled): with it both runs sample the reference's first film positions in every pixel.
        eq_pbrt_e=() eq_pbrt_t=()
        if [[ $pbrt_ok -eq 1 ]]; then
            eq_pbrt_spp="$(awk -v spp="$spp" -v s="${eq_illum_s:-$equal_time}" -v t="$pbrt_s" \
                'BEGIN { n = int(spp * s / t + 0.5); print (n < 1 ? 1 : n) }')"
            for seed in 1 2; do
                timed_run "$folder" "$scene_out/pbrt-equal-time-$seed.log" "$pbrt" --nthreads "$threads" \
                    --spp "$eq_pbrt_spp" --seed "$seed" --quiet \
                    --outfile "$scene_out/pbrt-equal-time-$seed.exr" test.pbrt || break
                [[ $seed -eq 2 ]] || eq_pbrt_s="$run_seconds"
                [[ ! -f "$reference" ]] ||
                    read -r "eq_pbrt_e[$seed]" "eq_pbrt_t[$seed]" \
                        <<<"$(rmse_against "$scene_out/pbrt-equal-time-$seed.exr" "$reference")"
            done
            eq_pbrt_rmse="$(calc 'sqrt((a1 * a1 + a2 * a2) / 2)' "${eq_pbrt_e[1]:-}" "${eq_pbrt_e[2]:-}")"
            eq_pbrt_trim="$(calc 'sqrt((a1 * a1 + a2 * a2) / 2)' "${eq_pbrt_t[1]:-}" "${eq_pbrt_t[2]:-}")"
        fi
        [[ -f "$reference" ]] || echo "compare_peers.sh: no reference $reference: no RMSE for $scene" >&2
        row+=("$equal_time" "$eq_illum_spp" "$(fmt %.2f "$eq_illum_s")" "$(fmt %.5g "$eq_illum_rmse")"
              "$eq_pbrt_spp" "$(fmt %.2f "$eq_pbrt_s")" "$(fmt %.5g "$eq_pbrt_rmse")"
              "$(fmt %.2f "$(calc 'a1 / a2' "$eq_pbrt_rmse" "$eq_illum_rmse")")"
              "$(fmt %.5g "$eq_illum_trim")" "$(fmt %.5g "$eq_pbrt_trim")"
              "$(fmt %.2f "$(calc 'a1 / a2' "$eq_pbrt_trim" "$eq_illum_trim")")")
    fi
    rows+=("$(join_cells "${row[@]}")")
    (IFS=,; echo "${row[*]}") >>"$csv"

    # Cycles: the Cornell box only (scripts/cycles_cornell.py builds that one scene). Cycles is an RGB
    # renderer, so its counterpart is illum in RGB mode, timed here as well; illum's render-only time
    # is its --stats "seconds" (sampling, after parsing and set-up), Blender's is its "Time:" (scene
    # sync, BVH and sampling, after start-up and building the scene in Python).
    if [[ -n "$blender" && "$scene" == cornell-box ]]; then
        cycles_times=() cycles_render=() cycles_rss=() rgb_times=() rgb_render=() rgb_rss=()
        cycles_ok=1 rgb_ok=1
        for ((run = 1; run <= runs; run++)); do
            if [[ $cycles_ok -eq 1 ]] && timed_run "$scene_out" "$scene_out/cycles.$run.log" "$blender" -b \
                --factory-startup -noaudio --python "$script_dir/cycles_cornell.py" -- \
                --scene "$folder/test.pbrt" --spp "$spp" --threads "$threads" \
                --resolution "$width" "$height" --out "$scene_out/cycles.exr"; then
                cycles_times+=("$run_seconds")
                cycles_rss+=("$run_rss_kb")
                cycles_render+=("$(blender_render_seconds "$scene_out/cycles.$run.log")")
            else
                cycles_ok=0
            fi
            if [[ $rgb_ok -eq 1 ]] && timed_run "$folder" "$scene_out/illum-rgb.$run.log" "$illum" render \
                test.pbrt --threads "$threads" --spp "$spp" -o "$scene_out/illum-rgb.exr" --quiet \
                --stats "$scene_out/illum-rgb.$run.json"; then
                rgb_times+=("$run_seconds")
                rgb_rss+=("$run_rss_kb")
                rgb_render+=("$(json_field "$scene_out/illum-rgb.$run.json" seconds)")
            else
                rgb_ok=0
            fi
        done
        if [[ $cycles_ok -eq 1 && $rgb_ok -eq 1 ]]; then
            c_s="$(median "${cycles_times[@]}")"
            c_r="$(median "${cycles_render[@]}")"
            i_s="$(median "${rgb_times[@]}")"
            i_r="$(median "${rgb_render[@]}")"
            rgb_mib="$(calc 'a1 / 1024' "$(median "${rgb_rss[@]}")")"
            cycles_mib="$(calc 'a1 / 1024' "$(median "${cycles_rss[@]}")")"
            cycles_row="$(join_cells "$scene" "${width}x$height" "$spp" "$(fmt %.3f "$i_s")" \
                "$(fmt %.3f "$i_r")" "$(fmt %.1f "$rgb_mib")" "$(fmt %.3f "$c_s")" "$(fmt %.3f "$c_r")" \
                "$(fmt %.1f "$cycles_mib")" "$(fmt %.2f "$(calc 'a1 / a2' "$c_s" "$i_s")")" \
                "$(fmt %.2f "$(calc 'a1 / a2' "$c_r" "$i_r")")")"
        fi
    fi
done

# ---------------------------------------------------------------------------------------------------
# The tables.

markdown_header() {
    local line="|" rule="|" title
    for title in "$@"; do line+=" $title |"; rule+="---|"; done
    echo "$line"
    echo "$rule"
}

# awk, not "read -a", splits the cells: read drops a trailing empty cell.
markdown_row() {
    awk -F "$separator" '{ line = "|"
        for (i = 1; i <= NF; i++) line = line " " ($i == "" ? "-" : $i) " |"
        print line }' <<<"$1"
}

markdown_header "${titles[@]}"
for row in "${rows[@]}"; do markdown_row "$row"; done
echo
echo "Times are the median wall time of $runs whole processes (start-up, parsing and writing the image" \
     "included); Msamples/s = width x height x spp / that time. pbrt/illum above 1: illum is faster."
if [[ -n "$equal_time" ]]; then
    echo "Equal time: RMSE over all pixels and channels against refs/spectral/<scene>.exr;" \
         "RMSE pbrt/illum above 1: illum's image is closer at equal time. Trimmed: the same without the" \
         "0.1% of each image's pixels with the largest errors (illum diff --trim; fireflies)." \
         "pbrt-v4 renders with seeds 1 and 2 (its RMSE: the root mean square of the two runs')."
fi

if [[ -n "$cycles_row" ]]; then
    cycles_csv="$out_dir/cycles.csv"
    (IFS=,; echo "${cycles_columns[*]}") >"$cycles_csv"
    echo
    markdown_header "${cycles_titles[@]}"
    markdown_row "$cycles_row"
    echo "${cycles_row//"$separator"/,}" >>"$cycles_csv"
    echo
    echo "Cycles against illum in RGB mode (Cycles is an RGB renderer). Whole process: median wall time;" \
         "render: Blender's own 'Time:' against illum's --stats seconds."
elif [[ -n "$blender" ]]; then
    echo
    echo "Cycles: no row (it renders only the Cornell box, which was not among the scenes, or it failed)."
fi
echo
echo "CSV: $csv${cycles_row:+ and $out_dir/cycles.csv}"
