#!/usr/bin/env bash
# Builds the fuzz targets with clang's libFuzzer (plus AddressSanitizer and
# UndefinedBehaviorSanitizer) and runs each one for a while over the seed corpus.
#
#   tests/fuzz/run.sh [SECONDS_PER_TARGET]      (default 20)
#
# Needs clang++ and the libFuzzer runtime (Debian: clang, libclang-rt-14-dev). Builds in
# build/fuzz (or $IMPASTO_FUZZ_BUILD); new corpus entries and crash files stay there.
set -euo pipefail

seconds="${1:-20}"
repo="$(cd "$(dirname "$0")/../.." && pwd)"
files="$repo/tests/data/files"  # the real recordings, copied into the repository
build="${IMPASTO_FUZZ_BUILD:-$repo/build/fuzz}"
cxx="${CXX_FUZZ:-clang++}"
flags=(-std=c++20 -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined
       -fno-sanitize-recover=undefined -I"$repo/input/include" -I"$repo/paintcore/include"
       -I"$repo/files/include" -I"$repo/util/include"
       -DIMPASTO_SOURCE_DATA_DIR=\"$repo/data\" -DIMPASTO_BUILD_DIR=\"$build\")

mkdir -p "$build/obj"
echo "building the input library (and the files and util modules it uses) with $cxx"
objects=()
pids=()
for source in "$repo"/input/src/*.cpp "$repo"/files/src/*.cpp "$repo"/util/src/*.cpp; do  # one compiler per core at a time
  object="$build/obj/$(basename "${source%.cpp}").o"
  "$cxx" "${flags[@]}" -fsanitize=fuzzer-no-link -I"$repo/input/src" -c "$source" -o "$object" &
  pids+=($!)
  objects+=("$object")
  if [ "${#pids[@]}" -ge "$(nproc)" ]; then
    wait "${pids[0]}"
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid"; done

declare -A seeds=(
  [hid_descriptor]="$repo/tests/fuzz/corpus/hid $files/hid"
  [hid_recording]="$repo/tests/fuzz/corpus/hid_recording $files/hid"
  [hid_capture]="$repo/tests/fuzz/corpus/hid_capture $files/hid/captures/Huion_H610 $files/hid/captures/Ugee_M708_v2 $repo/data/tablets"
  [stroke_reader]="$repo/tests/fuzz/corpus/strokes $files/strokes"
)

status=0
for target in hid_descriptor hid_recording hid_capture stroke_reader; do
  binary="$build/fuzz_$target"
  "$cxx" "${flags[@]}" -fsanitize=fuzzer "$repo/tests/fuzz/fuzz_$target.cpp" "${objects[@]}" \
    -o "$binary"
  corpus="$build/corpus_$target"  # the fuzzer adds what it finds here, not in the repo
  mkdir -p "$corpus"
  existing=()
  for dir in ${seeds[$target]}; do
    [[ -d "$dir" ]] && existing+=("$dir")
  done
  echo "fuzzing $target for ${seconds}s"
  if ! "$binary" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -artifact_prefix="$build/crash_${target}_" -print_final_stats=1 \
      "$corpus" "${existing[@]}" 2>"$build/fuzz_$target.log"; then
    echo "FAILED: $target (see $build/fuzz_$target.log and $build/crash_${target}_*)"
    tail -40 "$build/fuzz_$target.log"
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz_$target.log" || true
  fi
done
exit $status
