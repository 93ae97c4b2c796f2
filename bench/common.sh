# SPDX-License-Identifier: Apache-2.0
# Shared by the whole-process benchmark scripts (sourced, not run).

# Makes a scratch directory, removed on exit, and works in it, with no colour config or
# cache from the environment; sets `repo` (this checkout) and `samples` (its samples).
bench_workdir() {
  repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  samples="$repo/data/samples"
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  cd "$work"
  unset OCIO TEXSYN_CACHE
}

# Runs a command; prints "seconds peak_MB" (wall time, the child's largest resident set).
measure() {
  /usr/bin/python3 - "$@" <<'PY'
import resource, subprocess, sys, time
t0 = time.perf_counter()
subprocess.run(sys.argv[1:], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
t = time.perf_counter() - t0
print("%.3f %.1f" % (t, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024))
PY
}

# The median of the arguments (the upper one of an even count).
median() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
