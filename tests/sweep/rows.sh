#!/usr/bin/env bash
# CTest driver of `soma sweep` (issue 26): the rows of one process, of TBB threads and of
# `mpirun -np 2` compared row for row; a sweep killed with SIGKILL and resumed gives the same rows.
# Rows are compared without their last field, the wall seconds.
# mpiresume: the same kill and resume under `mpirun -np 2` (the whole job killed, its process group),
# the rows identical to the single-process run.
# mpibad: a bad sweep under `mpirun -np 2` is said once (rank 0), exit non-zero, no rows.
# Usage: rows.sh parallel|resume SOMA REPO WORK [MPIEXEC]; rows.sh mpiresume|mpibad SOMA REPO WORK MPIEXEC
set -euo pipefail
mode=$1 soma=$2 repo=$3 work=$4 mpiexec=${5:-}
rm -rf "$work" && mkdir -p "$work"
strip() {  # a rows file without the seconds: JSON Lines' last key, CSV's last column
  case "$1" in
    *.jsonl) sed -e 's/,"seconds":[^,}]*}$/}/' "$1" ;;
    *.csv) sed -e 's/,[^,]*$//' "$1" ;;
  esac
}
same() {  # same DIR_A DIR_B: identical rows, both files
  for f in rows.csv rows.jsonl; do
    if ! cmp -s <(strip "$1/$f") <(strip "$2/$f"); then
      echo "FAIL: $1/$f and $2/$f differ:"; diff <(strip "$1/$f") <(strip "$2/$f") | head -20; exit 1
    fi
  done
}
lines() { if [ -f "$1" ]; then wc -l < "$1"; else echo 0; fi; }

case "$mode" in
parallel)
  sweep=$repo/tests/sweep/cusps_small.json
  "$soma" sweep "$sweep" --out "$work/one" --threads 1 --quiet
  "$soma" sweep "$sweep" --out "$work/tbb" --threads 2 --quiet
  same "$work/one" "$work/tbb"
  n=$(lines "$work/one/rows.jsonl")
  [ "$n" = 12 ] || { echo "FAIL: $n rows, expected 12"; exit 1; }
  # The counts of the 0-, 2- and 4-cusp domains (the same arms in tests/sweep/sweep.cpp, checked there
  # against the traced second method): a2 = 0.5, 1, 2, 3.5 (slowest) x a3 = 0.25, 1.25, 2.75.
  counts=$(cut -d, -f5 "$work/one/rows.csv" | tail -n +2 | tr '\n' ' ')
  [ "$counts" = "4 0 0 0 2 2 4 4 2 4 4 4 " ] || { echo "FAIL: cusp counts $counts"; exit 1; }
  if grep -v '"status":"ok"' "$work/one/rows.jsonl"; then echo "FAIL: a row is not ok"; exit 1; fi
  if [ -n "$mpiexec" ]; then
    "$mpiexec" --allow-run-as-root --oversubscribe -np 2 "$soma" sweep "$sweep" --out "$work/mpi" --threads 1 --quiet \
      > "$work/mpi.txt"
    cat "$work/mpi.txt"
    grep -q "on 2 ranks" "$work/mpi.txt" || { echo "FAIL: mpirun -np 2 did not run on 2 ranks"; exit 1; }
    same "$work/one" "$work/mpi"
  fi
  echo "PASS: 12 rows identical on 1 thread, 2 TBB threads${mpiexec:+ and mpirun -np 2}"
  ;;
resume)
  sweep=$repo/tests/sweep/ur5_resume.json
  total=400
  "$soma" sweep "$sweep" --out "$work/reference" --quiet
  # Killed (SIGKILL: nothing flushed on the way out) once some rows are written ...
  "$soma" sweep "$sweep" --out "$work/resumed" --threads 1 --quiet & pid=$!
  for _ in $(seq 1 600); do
    [ "$(lines "$work/resumed/rows.jsonl")" -ge 40 ] && break
    sleep 0.02
  done
  kill -KILL $pid 2>/dev/null || true
  wait $pid 2>/dev/null || true
  written=$(lines "$work/resumed/rows.jsonl")
  echo "killed after $written of $total rows"
  [ "$written" -gt 0 ] && [ "$written" -lt $total ] || { echo "FAIL: the kill did not land mid-run ($written rows)"; exit 1; }
  # ... and its last row cut in the middle, as a kill during the write would leave it.
  size=$(stat -c %s "$work/resumed/rows.jsonl")
  truncate -s $((size - 9)) "$work/resumed/rows.jsonl"
  "$soma" sweep "$sweep" --out "$work/resumed" --quiet > "$work/rerun.txt"
  cat "$work/rerun.txt"
  grep -q "$total points: $((written - 1)) already written, $((total - written + 1)) computed" "$work/rerun.txt" ||
    { echo "FAIL: the rerun did not skip the $((written - 1)) complete rows"; exit 1; }
  same "$work/reference" "$work/resumed"
  # A third run has nothing left to do.
  "$soma" sweep "$sweep" --out "$work/resumed" --quiet | grep -q "$total already written, 0 computed" ||
    { echo "FAIL: a complete sweep was recomputed"; exit 1; }
  # Another sweep into the same folder is refused (exit 2), the rows untouched.
  set +e
  "$soma" sweep "$repo/examples/sweeps/cusps_orthogonal_3r.json" --out "$work/resumed" --quiet 2> "$work/other.txt"
  rc=$?
  set -e
  [ $rc = 2 ] && grep -q "holds the rows of another sweep" "$work/other.txt" ||
    { echo "FAIL: another sweep into the same --out: exit $rc"; cat "$work/other.txt"; exit 1; }
  same "$work/reference" "$work/resumed"
  echo "PASS: killed at $written rows, resumed, $total rows identical to the uninterrupted run"
  ;;
mpiresume)
  [ -n "$mpiexec" ] || { echo "FAIL: mpiresume needs MPIEXEC"; exit 1; }
  sweep=$repo/tests/sweep/ur5_resume.json
  total=400
  mpi=("$mpiexec" --allow-run-as-root --oversubscribe -np 2 "$soma" sweep "$sweep" --threads 1 --quiet)
  "$soma" sweep "$sweep" --out "$work/reference" --threads 1 --quiet
  "${mpi[@]}" --out "$work/resumed" > "$work/killed.txt" 2>&1 & pid=$!
  # Rank 0 writes each chunk as it arrives (guided chunks: the first are 50 points): kill at the first.
  for _ in $(seq 1 3000); do
    [ "$(lines "$work/resumed/rows.jsonl")" -ge 1 ] && break
    sleep 0.005
  done
  # Open MPI puts the ranks in process groups of their own: SIGKILL to mpirun and every descendant.
  tree() { local c; for c in $(pgrep -P "$1"); do echo "$c"; tree "$c"; done; }
  victims=$(echo $pid; tree $pid)
  kill -KILL $victims 2>/dev/null || true
  wait $pid 2>/dev/null || true
  for _ in $(seq 1 500); do
    alive=0; for v in $victims; do kill -0 "$v" 2>/dev/null && alive=1; done
    [ $alive = 0 ] && break; sleep 0.01
  done
  written=$(lines "$work/resumed/rows.jsonl")
  echo "mpirun -np 2 killed after $written of $total rows"
  [ "$written" -gt 0 ] && [ "$written" -lt $total ] || { echo "FAIL: the kill did not land mid-run ($written rows)"; exit 1; }
  "${mpi[@]}" --out "$work/resumed" > "$work/rerun.txt"
  cat "$work/rerun.txt"
  grep -q "on 2 ranks" "$work/rerun.txt" || { echo "FAIL: the resumed run did not run on 2 ranks"; exit 1; }
  [ $alive = 0 ] || { echo "FAIL: a rank outlived SIGKILL"; exit 1; }
  grep -q "$total points: $written already written, $((total - written)) computed" "$work/rerun.txt" ||
    { echo "FAIL: the resumed run did not skip exactly the $written complete rows"; exit 1; }
  same "$work/reference" "$work/resumed"
  echo "PASS: mpirun -np 2 killed at $written rows, resumed on 2 ranks, $total rows identical to the single-process run"
  ;;
mpibad)
  # A bad sweep under mpirun -np 2: every rank meets the defect, rank 0 alone says it, the job exits 2.
  [ -n "$mpiexec" ] || { echo "FAIL: mpibad needs MPIEXEC"; exit 1; }
  rc=0
  "$mpiexec" --allow-run-as-root --oversubscribe -np 2 "$soma" sweep "$repo/tests/sweep/bad/empty_range.json" \
    --out "$work/bad" --quiet > "$work/bad.txt" 2>&1 || rc=$?
  cat "$work/bad.txt"
  said=$(grep -c "^soma: .*empty_range.json" "$work/bad.txt" || true)
  [ "$said" = 1 ] || { echo "FAIL: the defect was said $said times (once expected)"; exit 1; }
  [ "$rc" != 0 ] || { echo "FAIL: mpirun exited 0"; exit 1; }
  [ ! -e "$work/bad/rows.jsonl" ] || { echo "FAIL: rows written for a bad sweep"; exit 1; }
  echo "PASS: a bad sweep under mpirun -np 2 said once (exit $rc), no rows"
  ;;
esac
