#!/usr/bin/env bash
# The library as others use it: install the build into a fresh prefix, build a project that
# calls find_package(ghclip), run it.
#   install_test.sh BUILD_DIR CONSUMER_SOURCE_DIR
set -euo pipefail
BUILD="$1"
CONSUMER="$2"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
cmake --install "$BUILD" --prefix "$TMP/prefix" >/dev/null
test -f "$TMP/prefix/include/ghclip/clip.h"
gen=()
command -v ninja >/dev/null && gen=(-G Ninja)
cmake -S "$CONSUMER" -B "$TMP/build" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$TMP/prefix" >/dev/null
cmake --build "$TMP/build" >/dev/null
"$TMP/build/consumer"
