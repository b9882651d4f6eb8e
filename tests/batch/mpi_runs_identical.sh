#!/usr/bin/env bash
# `mpirun -n 2 --oversubscribe framedyn batch` gives a runs.csv byte-identical to
# the same design on one thread and on two threads (issue 19): a Latin hypercube
# of 8 runs of the shipped 2-D plow study. Usage: mpi_runs_identical.sh FRAMEDYN SOURCE_DIR WORK_DIR
set -euo pipefail
framedyn=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
cp "$src/examples/r100_plow_2d_vertical_path.yaml" study.yaml
cat > design.yaml <<'YAML'
framedyn_batch: 1
study: study.yaml
sampling: {method: latin_hypercube, samples: 8, seed: 7}
parameters:
  - {key: soil.damping, distribution: uniform, low: 150, high: 450}
  - {key: plow.shaker.frequency_hz, distribution: truncated_normal, mean: 18.33, std_dev: 1, low: 16, high: 20}
outputs:
  - rigid.response.peak_cutting_force
  - rigid.modes[0].frequency
YAML
"$framedyn" batch design.yaml --out one -j 1 -q
"$framedyn" batch design.yaml --out two -j 2 -q
# The manager (rank 0) hands runs to the worker; run as root in containers, hence the two variables.
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n 2 --oversubscribe "$framedyn" batch design.yaml --out mpi2 -q
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n 1 "$framedyn" batch design.yaml --out mpi1 -q
cmp one/runs.csv two/runs.csv
cmp one/runs.csv mpi2/runs.csv
cmp one/runs.csv mpi1/runs.csv
cmp one/summary.json mpi2/summary.json
[ "$(wc -l < one/runs.csv)" -eq 9 ] && ! grep -q ",failed," one/runs.csv
echo "runs.csv identical on 1 and 2 threads and 1 and 2 MPI ranks"
