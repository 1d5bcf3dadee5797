# What the script tests share, sourced with the test's own arguments (ILLUM REPO): strict mode, illum and
# repo from the arguments, a temporary folder removed on exit, and fail MESSAGE.
set -euo pipefail
illum="$1"
repo="$2"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

fail() {
    echo "FAIL: $*" >&2
    exit 1
}
