#!/usr/bin/env bash
# Builds the content fuzz targets (clang, libFuzzer + ASan + UBSan) and runs each for a
# bounded time, then the frame settings fuzzer against the ASan build when it is there. Exit status 1 when any target finds a crash, leak, hang or trap; the input is
# left in <build>/fuzz-artifacts/ and should be added to tests/content/regressions/<kind>/.
#
#   tests/content/run_fuzzers.sh [seconds-per-target=60]
# Environment: CANDELA_FUZZ_BUILD (default <repo>/build-fuzz), CANDELA_SHARED_ASSETS.
set -euo pipefail
seconds=${1:-60}
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${CANDELA_FUZZ_BUILD:-$repo/build-fuzz}
assets=${CANDELA_SHARED_ASSETS:-$repo/../shared/assets}
here=$repo/tests/content

CC=clang CXX=clang++ cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCANDELA_SANITIZE=address,undefined,fuzzer-no-link -DCANDELA_SHARED_ASSETS="$assets" >/dev/null
ninja -C "$build" fuzz_gltf_loader fuzz_scene_file fuzz_exr_image fuzz_audio_clip

# Seed corpora: the repo's seeds and regressions plus small real assets (the large models
# would only slow each iteration down). Working corpora live in the build folder.
seed() {  # seed <target> <files...>
  local corpus=$build/fuzz-corpus/$1
  shift
  mkdir -p "$corpus"
  for f in "$@"; do [ -f "$f" ] && cp -f "$f" "$corpus/"; done
  return 0
}
shopt -s nullglob
seed fuzz_gltf_loader "$here"/fuzz/seeds/gltf/* "$here"/regressions/gltf/* \
  "$assets"/models/Box/Box.glb "$assets"/models/BoxTextured/BoxTextured.glb \
  "$assets"/models/TextureSettingsTest/TextureSettingsTest.glb
seed fuzz_scene_file "$here"/fuzz/seeds/scene/* "$here"/regressions/scene/*
seed fuzz_exr_image "$here"/regressions/exr/* "$assets"/bad/exr/*.exr
seed fuzz_audio_clip "$repo"/tests/audio/sounds/tone_1khz.ogg "$repo"/runtime/examples/*/sounds/*.wav \
  "$repo"/runtime/examples/orb_game/sounds/*.ogg

status=0
mkdir -p "$build/fuzz-artifacts"
for target in fuzz_gltf_loader fuzz_scene_file fuzz_exr_image fuzz_audio_clip; do
  echo "== $target for ${seconds}s"
  if ! "$build/bin/$target" "$build/fuzz-corpus/$target" -max_total_time="$seconds" \
      -timeout=20 -rss_limit_mb=2560 -max_len=65536 -print_final_stats=1 \
      -artifact_prefix="$build/fuzz-artifacts/$target-" 2>"$build/fuzz-artifacts/$target.log"; then
    echo "!! $target failed; see $build/fuzz-artifacts/$target.log and:"
    ls "$build/fuzz-artifacts/" | grep "^$target-" || true
    tail -40 "$build/fuzz-artifacts/$target.log"
    status=1
  else
    grep -E "stat::number_of_executed_units|cov:" "$build/fuzz-artifacts/$target.log" | tail -2
  fi
done
# The frame settings fuzzer (tests/runtime/fuzz_frame_settings.cpp): scene files of float edge
# cases rendered by the ASan build's candela, a fresh seed each run (printed, to replay).
asan=${CANDELA_ASAN_BUILD:-$repo/build-asan}
if [ -x "$asan/bin/fuzz_frame_settings" ] && [ -x "$asan/bin/candela" ]; then
  echo "== fuzz_frame_settings for ${seconds}s"
  if ! CANDELA_SHARED_ASSETS="$assets" ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1} \
      LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$repo/tests/sanitizers/lsan.supp:print_suppressions=0} \
      UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
      "$asan/bin/fuzz_frame_settings" --candela "$asan/bin/candela" --seconds "$seconds" \
      --out "$build/fuzz-artifacts/frame_settings"; then
    echo "!! fuzz_frame_settings failed; the inputs are in $build/fuzz-artifacts/frame_settings/"
    status=1
  fi
fi
exit $status
