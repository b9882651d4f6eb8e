#!/usr/bin/env bash
# Builds framedyn's libFuzzer harnesses with clang (ASan + UBSan) and runs each
# for a while, starting from the seed corpora (the shipped meshes and studies
# and tests/fuzz/seeds). Exits non-zero on the first finding and names the
# input that reproduces it. Each harness runs with its dictionary
# (tests/fuzz/dictionaries/).
#
#   tests/fuzz/run_fuzzers.sh build  SOURCE_DIR BUILD_DIR
#   tests/fuzz/run_fuzzers.sh run    SOURCE_DIR BUILD_DIR SECONDS HARNESS
#   tests/fuzz/run_fuzzers.sh coverage SOURCE_DIR COVERAGE_BUILD_DIR HARNESS CORPUS
#
# `coverage` builds HARNESS with clang's source-based coverage in a build
# directory of its own, replays CORPUS (a run's BUILD_DIR/corpus/HARNESS) and
# prints the line and branch coverage of the reader's own sources, and writes
# their uncovered lines to COVERAGE_BUILD_DIR/HARNESS-uncovered.txt: where
# the fuzzer has not been, to judge whether a campaign has seen the reader.
#
# HARNESS: fuzz_inp_reader | fuzz_study_reader | fuzz_load_history_reader. A finding is kept in
# BUILD_DIR/findings/; rerun it with `BUILD_DIR/tests/fuzz/HARNESS FILE`.
set -euo pipefail
what=$1 source_dir=$(cd "$2" && pwd) build_dir=$3

case "$what" in
  build)
    if ! command -v clang++ >/dev/null; then
      echo "run_fuzzers: clang++ not found (Debian packages clang and libclang-rt-14-dev; ./install-deps.sh installs them)" >&2
      exit 1
    fi
    # -O1 -g1, as the sanitized build: the harnesses' build is the fuzz tier's
    # longest step (about a fifth less compile time than RelWithDebInfo's -O2 -g,
    # measured on coupling/frame_study.cpp and fem/modal_analysis.cpp), and
    # ASan's reports stay exact with file:line.
    cmake -S "$source_dir" -B "$build_dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
      -DFRAMEDYN_FUZZ=ON -DFRAMEDYN_BUILD_TESTS=OFF -DFRAMEDYN_NATIVE=OFF >/dev/null
    cmake --build "$build_dir" -j2 --target fuzz_inp_reader fuzz_study_reader fuzz_load_history_reader
    ;;
  run)
    seconds=$4 harness=$5
    corpus="$build_dir/corpus/$harness"
    mkdir -p "$corpus" "$build_dir/findings"
    case "$harness" in
      fuzz_inp_reader)   cp "$source_dir"/meshes/*.inp "$source_dir"/tests/fuzz/seeds/inp/*.inp "$corpus"/; dict=inp ;;
      fuzz_study_reader) find "$source_dir/examples" -name '*.yaml' -exec cp {} "$corpus"/ \;
                         cp "$source_dir"/tests/fuzz/seeds/study/*.yaml "$corpus"/; dict=study ;;
      fuzz_load_history_reader) cp "$source_dir"/tests/fuzz/seeds/loads/*.csv "$corpus"/; dict=load_history ;;
      *) echo "run_fuzzers: unknown harness '$harness'" >&2; exit 2 ;;
    esac
    # -timeout: an input that takes 10 s is a hang, a finding too. -dict: the
    # reader's keywords and keys, and numbers at the edges of double's range,
    # which byte mutations alone rarely write (tests/fuzz/dictionaries/).
    "$build_dir/tests/fuzz/$harness" "$corpus" -dict="$source_dir/tests/fuzz/dictionaries/$dict.dict" \
      -max_total_time="$seconds" -max_len=20000 -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build_dir/findings/$harness-" 2>"$build_dir/$harness.log" || {
      tail -n 60 "$build_dir/$harness.log" >&2
      echo "run_fuzzers: $harness found a fault; reproducer in $build_dir/findings/" >&2
      exit 1
    }
    grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|Done)" "$build_dir/$harness.log" || true
    echo "run_fuzzers: $harness ran ${seconds} s without a finding; corpus $(ls "$corpus" | wc -l) inputs"
    ;;
  coverage)
    harness=$4 corpus=$5
    case "$harness" in
      fuzz_inp_reader)   sources="fem/inp_reader.cpp" ;;
      fuzz_study_reader) sources="coupling/yaml_input.cpp coupling/study_blocks.cpp coupling/rigid_study.cpp coupling/study_machine_2d.cpp coupling/study_machine_3d.cpp coupling/frame_study.cpp" ;;
      fuzz_load_history_reader) sources="coupling/load_history.cpp" ;;
      *) echo "run_fuzzers: unknown harness '$harness'" >&2; exit 2 ;;
    esac
    cmake -S "$source_dir" -B "$build_dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFRAMEDYN_FUZZ=ON \
      -DFRAMEDYN_BUILD_TESTS=OFF -DFRAMEDYN_NATIVE=OFF -DCMAKE_CXX_FLAGS="-fprofile-instr-generate -fcoverage-mapping" \
      -DCMAKE_EXE_LINKER_FLAGS="-fprofile-instr-generate" >/dev/null
    cmake --build "$build_dir" -j2 --target "$harness" >/dev/null
    rm -f "$build_dir/$harness.profraw"
    # -runs=0: read and run every input of the corpus once, then stop.
    LLVM_PROFILE_FILE="$build_dir/$harness.profraw" "$build_dir/tests/fuzz/$harness" -runs=0 -max_len=20000 -rss_limit_mb=2048 "$corpus" \
      2>"$build_dir/$harness-replay.log"
    llvm-profdata merge -sparse "$build_dir/$harness.profraw" -o "$build_dir/$harness.profdata"
    paths=(); for f in $sources; do paths+=("$source_dir/$f"); done
    llvm-cov report "$build_dir/tests/fuzz/$harness" -instr-profile="$build_dir/$harness.profdata" "${paths[@]}"
    # Lines with a count of 0 in llvm-cov's listing: "   NN|      0|code".
    llvm-cov show "$build_dir/tests/fuzz/$harness" -instr-profile="$build_dir/$harness.profdata" "${paths[@]}" \
      | awk '/^\/.*:$/ {file=$0} /^ *[0-9]+\| *0\|/ {print file " " $0}' >"$build_dir/$harness-uncovered.txt"
    echo "run_fuzzers: uncovered lines in $build_dir/$harness-uncovered.txt ($(wc -l <"$build_dir/$harness-uncovered.txt"))"
    ;;
  *) echo "usage: run_fuzzers.sh build|run|coverage SOURCE_DIR BUILD_DIR [SECONDS HARNESS | HARNESS CORPUS]" >&2; exit 2 ;;
esac
