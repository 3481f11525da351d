#!/usr/bin/env bash
# Builds the in-process fuzz target (readers.cc with abrade's common library, clang's libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer) and runs it on each format for RUNS inputs,
# from the seed corpus in tests/fuzz/libfuzzer/seeds/FORMAT. A finding (crash, sanitizer report,
# an exception other than InputError, an input that takes more than 10 s) fails the run and is
# kept in OUT/FORMAT/ as crash-* or timeout-*. Skipped (exit 77) where clang's libFuzzer is not
# installed (Debian: clang, libclang-rt-14-dev).
#   build_and_run.sh SOURCE_DIR BUILD_DIR OUT RUNS [FORMAT...]
#   (a campaign: build_and_run.sh . build /tmp/lf 5000 obj ply vtk stl vtp csv)
set -euo pipefail
src=$1 build=$2 out=$3 runs=$4
shift 4
formats=("$@")
((${#formats[@]})) || formats=(obj ply vtk stl vtp csv)
command -v clang++ > /dev/null && compgen -G "/usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a" > /dev/null ||
  { echo "clang's libFuzzer is not installed: skipped"; exit 77; }
mkdir -p "$out"
vtk=$(ls -d /usr/include/vtk-9* | head -1)
ver=${vtk##*/vtk-}
exe=$out/fuzz_readers
sources=("$src"/dem/source/common/*.cc "$src/tests/fuzz/libfuzzer/readers.cc")
newest=$(ls -t "${sources[@]}" "$src"/dem/include/abrade/common/*.h | head -1)
if [[ ! -x $exe || $newest -nt $exe ]]; then
  libs=()
  for m in CommonCore CommonDataModel CommonExecutionModel CommonMisc CommonSystem CommonTransforms CommonMath \
           FiltersCore FiltersGeneral FiltersGeometry FiltersSources IOCore IOGeometry IOLegacy IOXML IOXMLParser \
           IOPLY sys; do
    libs+=("-lvtk$m-$ver")
  done
  echo "building $exe (clang, libFuzzer, ASan, UBSan)"
  clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -I"$src/dem/include" -I"$build/dem/include" -I"$vtk" -I/usr/include/eigen3 \
    "${sources[@]}" -o "$exe" "${libs[@]}" -lpthread
fi
failed=0
for f in "${formats[@]}"; do
  mkdir -p "$out/$f/corpus" "$out/$f/work"
  cp -n "$src/tests/fuzz/libfuzzer/seeds/$f"/* "$out/$f/corpus/" 2> /dev/null || true
  log=$out/$f/log.txt
  if ABRADE_FUZZ_FORMAT=$f ABRADE_FUZZ_DIR=$out/$f/work ASAN_OPTIONS=detect_leaks=0 \
       "$exe" -runs="$runs" -timeout=10 -max_len=4096 -seed=1 -artifact_prefix="$out/$f/" \
       -print_final_stats=1 "$out/$f/corpus" > "$log" 2>&1; then
    echo "$f: $(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$') inputs, no finding"
  else
    echo "$f: FINDING (see $log, artifact in $out/$f/)"; tail -30 "$log"; failed=1
  fi
done
exit $failed
