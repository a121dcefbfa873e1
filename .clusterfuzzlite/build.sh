#!/bin/bash -eu
# Builds every fuzz target the way OSS-Fuzz and ClusterFuzzLite expect: compilers and flags from
# $CC $CXX $CFLAGS $CXXFLAGS, the engine from $LIB_FUZZING_ENGINE, sources in $SRC, binaries,
# seed corpora (zipped) and dictionaries into $OUT.
SOURCE="${SRC}/ghclip"
[[ -d "$SOURCE" ]] || SOURCE="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${WORK:-/tmp}/ghclip-fuzz-build"
# CGAL's arrangement iterators downcast in a way UBSan's vptr check flags inside CGAL itself.
CXXFLAGS="$CXXFLAGS -fno-sanitize=vptr"
# The judges too are built with the engine's sanitizers (CMakeLists.txt: GHCLIP_FUZZ_SANITIZE_JUDGES).
cmake -S "$SOURCE" -B "$BUILD" -G Ninja -DGHCLIP_FUZZ=ON -DGHCLIP_FUZZ_SANITIZE_JUDGES=ON -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_C_FLAGS="$CFLAGS" -DCMAKE_CXX_FLAGS="$CXXFLAGS"
TARGETS=(fuzz_clip_naive fuzz_clip_sweep fuzz_clip_exact fuzz_clip_exact_oracle fuzz_diff_vatti fuzz_read)
cmake --build "$BUILD" --target "${TARGETS[@]}"
for t in "${TARGETS[@]}"; do
  cp "$BUILD/bin/$t" "$OUT/"
  cp "$SOURCE/fuzz/$t.dict" "$OUT/$t.dict"
  # libFuzzer turns its input-length control off for a target with a custom mutator
  # (fuzz/new_problem_mutator.h); its default back on, as ./harness fuzz runs them. The entropic
  # schedule's rare features are its 100 rarest only (the harness's fuzz command says why).
  printf '[libfuzzer]\nlen_control = 100\nentropic_feature_frequency_threshold = 0\n' >"$OUT/$t.options"
  (cd "$SOURCE/fuzz/${t}_seed_corpus" && zip -q -r "$OUT/${t}_seed_corpus.zip" .)
done
