#!/usr/bin/env bash
# The mutation check: plants each mutant of tests/mutation/mutants.tsv, one at
# a time, builds only the test binaries that own it, runs their owning tests
# under a time limit, puts the file back whatever happens, and prints the
# table (mutant, owning tests, killed by, time) and the score.
#   usage: scripts/mutation_check.sh [--slice K/N | --id ID[,ID...]] [--repeat R]
#                                    [--list FILE] [--build DIR] [--jobs J] [--timeout S]
#   --slice K/N   mutants whose row number i (1-based) has i % N == K % N
#                 (CI: K = the day number, so N days cover the list)
#   --repeat R    run the owning tests R times per mutant: a kill must be the
#                 same on every run, else the mutant is reported FLAKY
# The list (tab-separated, '#' comments): id, file, exact text, replacement,
# owning tests (binary:gtest_filter[;binary:filter...]), and "equivalent: why"
# or "survives: why" (a known survivor: counted, not killed, and no failure
# of the check) or empty. In the texts, \n and \t stand for a newline and a
# tab. A text not found exactly once is a STALE mutant: reported, a failure
# of the check (exit 1), never skipped silently. Exit 0 when every counted
# mutant is killed on every run, known survivors aside (the score counts them).
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD
list=tests/mutation/mutants.tsv build=build/release jobs=2 limit=300 repeat=1 slice="" ids=""
while [ $# -gt 0 ]; do
  case $1 in
    --slice) slice=$2; shift 2 ;;
    --id) ids=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --list) list=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --timeout) limit=$2; shift 2 ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    *) echo "mutation_check: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ -f "$list" ] || { echo "mutation_check: no list '$list'" >&2; exit 2; }
[ -f "$build/CMakeCache.txt" ] || { echo "mutation_check: '$build' is not a configured build folder (cmake --preset release -DTUMBLE_BUILD_TESTS=ON)" >&2; exit 2; }
if [ -n "$slice" ]; then
  case $slice in */*) ;; *) echo "mutation_check: --slice expects K/N, found '$slice'" >&2; exit 2 ;; esac
  sk=${slice%/*} sn=${slice#*/}
  [ "$sn" -ge 1 ] 2>/dev/null && [ "$sk" -ge 0 ] 2>/dev/null || { echo "mutation_check: --slice expects K/N with N >= 1, found '$slice'" >&2; exit 2; }
fi

work=$(mktemp -d)
backup="" target_file=""
restore() {  # the mutated file back, byte for byte (and its time, so make sees a change)
  if [ -n "$backup" ] && [ -f "$backup" ]; then cp "$backup" "$target_file" && touch "$target_file"; fi
  backup=""
}
cleanup() { restore; rm -rf "$work"; }
trap cleanup EXIT
trap 'echo "mutation_check: interrupted; the file is restored" >&2; exit 130' INT TERM HUP

# Applies one mutant with Python (exact text, exactly once): 0 applied, 3 stale.
apply() {  # file find replace
  python3 - "$1" "$2" "$3" <<'EOF'
import sys
path, find, repl = sys.argv[1:4]
unesc = lambda s: s.replace("\\n", "\n").replace("\\t", "\t")
find, repl = unesc(find), unesc(repl)
text = open(path, encoding="utf-8").read()
n = text.count(find)
if n != 1:
    print(f"found {n} times", file=sys.stderr)
    sys.exit(3)
open(path, "w", encoding="utf-8").write(text.replace(find, repl, 1))
EOF
}

binary_path() {  # test binary name -> path in the build folder
  find "$build/tests" -type f -name "$1" -perm -u+x 2>/dev/null | head -n 1
}

# One run of the owning tests: prints the first failing test (or "timeout",
# or "" when all pass).
run_owning() {  # tests spec
  local spec=$1 item bin filter path log
  IFS=';' read -ra items <<<"$spec"
  for item in "${items[@]}"; do
    bin=${item%%:*} filter=${item#*:}
    [ "$filter" = "$item" ] && filter="*"
    path=$(binary_path "$bin")
    [ -n "$path" ] || { echo "no-binary:$bin"; return; }
    log=$work/run.log
    timeout -k 5 "$limit" "$path" --gtest_filter="$filter" --gtest_brief=1 >"$log" 2>&1
    local rc=$?
    if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then echo "timeout($bin)"; return; fi
    if [ $rc -ne 0 ]; then
      local failed
      failed=$(grep -m1 -oE '^\[  FAILED  \] [A-Za-z0-9_/.]+' "$log" | sed 's/^\[  FAILED  \] //')
      echo "${failed:-crash(rc $rc)}"
      return
    fi
    grep -q '^\[  PASSED  \] 0 tests' "$log" && { echo "no-tests:$bin:$filter"; return; }
  done
  echo ""
}

printf '%-5s %-40s %-52s %-58s %6s\n' id "file" "owning tests" "killed by" "time"
built="" total=0 killed=0 survived=0 stale=0 equiv=0 flaky=0 broken=0 row=0
survivors=""
while IFS=$'\037' read -r id file find repl tests equivalent || [ -n "${id:-}" ]; do
  case $id in ''|'#'*) continue ;; esac
  row=$((row + 1))
  if [ -n "$slice" ] && [ $((row % sn)) -ne $((sk % sn)) ]; then continue; fi
  if [ -n "$ids" ] && [[ ",$ids," != *",$id,"* ]]; then continue; fi
  start=$SECONDS
  known=""
  case ${equivalent:-} in survives:*) known=${equivalent#survives: }; equivalent="" ;; esac
  if [ -n "${equivalent:-}" ]; then
    equiv=$((equiv + 1))
    printf '%-5s %-40s %-52s %-58s %6s\n' "$id" "$file" "$tests" "EQUIVALENT (${equivalent#equivalent: })" "-"
    continue
  fi
  total=$((total + 1))
  target_file=$root/$file
  if [ ! -f "$target_file" ]; then
    stale=$((stale + 1)); printf '%-5s %-40s %-52s %-58s %6s\n' "$id" "$file" "$tests" "STALE (no such file)" "-"; continue
  fi
  backup=$work/backup
  cp "$target_file" "$backup"
  if ! apply "$target_file" "$find" "$repl" 2>"$work/apply.err"; then
    backup=""
    stale=$((stale + 1))
    printf '%-5s %-40s %-52s %-58s %6s\n' "$id" "$file" "$tests" "STALE (text $(cat "$work/apply.err"))" "-"
    continue
  fi
  # Only the owning binaries (their dependencies, the mutated library among them).
  targets=$(tr ';' '\n' <<<"$tests" | sed 's/:.*//' | sort -u | tr '\n' ' ')
  result=""
  built="$built $targets"
  # shellcheck disable=SC2086
  if ! cmake --build "$build" -j "$jobs" --target $targets >"$work/build.log" 2>&1; then
    result="BUILD-FAILED"
  else
    results=()
    for ((r = 0; r < repeat; r++)); do results+=("$(run_owning "$tests")"); done
    result=${results[0]}
    for x in "${results[@]}"; do [ "$x" = "$result" ] || { [ -n "$x" ] && [ -n "$result" ]; } || result="FLAKY(${results[*]})"; done
  fi
  restore
  t=$((SECONDS - start))
  case $result in
    BUILD-FAILED) broken=$((broken + 1)); shown="BUILD FAILED (not a valid mutant: fix the list)" ;;
    FLAKY*) flaky=$((flaky + 1)); shown=$result; survivors="$survivors $id" ;;
    no-binary*|no-tests*) broken=$((broken + 1)); shown="NOT RUN ($result)" ;;
    "") survived=$((survived + 1))
        if [ -n "$known" ]; then shown="SURVIVED (known: $known)"; else shown="SURVIVED"; survivors="$survivors $id"; fi ;;
    *) killed=$((killed + 1)); shown=$result; [ "$repeat" -gt 1 ] && shown="$shown (x$repeat)"
       [ -n "$known" ] && shown="$shown; listed as a survivor: update the list" ;;
  esac
  printf '%-5s %-40s %-52s %-58s %5ss\n' "$id" "$file" "$tests" "$shown" "$t"
done < <(tr '\t' '\037' <"$list")  # not tabs: read would merge the empty fields between them
# Put back the object files of the original sources (ccache makes this quick).
# shellcheck disable=SC2046
[ -n "$built" ] && cmake --build "$build" -j "$jobs" --target $(tr ' ' '\n' <<<"$built" | grep . | sort -u) >/dev/null 2>&1
echo
echo "mutants: $total counted, $equiv equivalent (not counted); killed $killed, survived $survived, flaky $flaky, stale $stale, not run $broken"
if [ "$total" -gt 0 ]; then
  awk -v k="$killed" -v t="$total" 'BEGIN { printf "score: %d of %d killed (%.1f %%)\n", k, t, 100 * k / t }'
fi
[ -n "$survivors" ] && echo "not killed (unexpected):$survivors"
[ -z "$survivors" ] && [ "$stale" -eq 0 ] && [ "$broken" -eq 0 ] && [ "$flaky" -eq 0 ]
