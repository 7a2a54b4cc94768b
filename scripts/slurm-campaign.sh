#!/usr/bin/env bash
# A certification campaign as a Slurm job array: one shard per array task, then a job that merges
# the shards' summaries into the report (docs/certification.md's form). The cases are those of
# `cutcom certify --seed S` on one machine: case k is the same program in any sharding.
#
#   bash scripts/slurm-campaign.sh --seed 20261127 --cases 1000000 --tasks 100 --out /shared/camp \
#        [--cutcom build/cli/cutcom] [--spec spec] [--budget 60] [--partition P] [--time 04:00:00]
#        [--wait]
#
# --out must be a folder every node sees. Each task runs `cutcom certify --shard I/N --jobs 1`
# (one core per task: Slurm places the tasks) and writes shard-I.json (summary), results-I.jsonl
# (one line per case) and, for an unexplained divergence, the program into corpus/. The merge job
# runs whatever the tasks' exit status (a shard that found a divergence stops early and says so in
# its summary) and writes certification.md, its histogram and merged.json. With --wait the script
# waits for the merge and prints the campaign's summary line; its exit status is the merge's.
set -euo pipefail

seed="" cases="" tasks="" out="" budget=60 partition="" limit="" wait=0
here=$(cd "$(dirname "$0")/.." && pwd)
cutcom="$here/build/cli/cutcom" spec="$here/spec"
usage() { sed -n '2,15p' "$0" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seed) seed=$2; shift 2 ;;
    --cases) cases=$2; shift 2 ;;
    --tasks) tasks=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --cutcom) cutcom=$2; shift 2 ;;
    --spec) spec=$2; shift 2 ;;
    --budget) budget=$2; shift 2 ;;
    --partition) partition=$2; shift 2 ;;
    --time) limit=$2; shift 2 ;;
    --wait) wait=1; shift ;;
    -h|--help) usage ;;
    *) echo "slurm-campaign: unknown argument '$1'" >&2; usage ;;
  esac
done
[[ -n "$seed" && -n "$cases" && -n "$tasks" && -n "$out" ]] || { echo "slurm-campaign: --seed, --cases, --tasks and --out are needed" >&2; usage; }
[[ "$cases" =~ ^[0-9]+$ && "$tasks" =~ ^[1-9][0-9]*$ && "$seed" =~ ^[0-9]+$ ]] || { echo "slurm-campaign: --seed, --cases and --tasks are whole numbers (--tasks from 1)" >&2; exit 2; }
command -v sbatch >/dev/null || { echo "slurm-campaign: sbatch not found (no Slurm here)" >&2; exit 2; }
[[ -x "$cutcom" ]] || { echo "slurm-campaign: $cutcom is not an executable (build first, or give --cutcom)" >&2; exit 2; }
[[ -d "$spec" ]] || { echo "slurm-campaign: $spec is not the spec folder (give --spec)" >&2; exit 2; }
cutcom=$(realpath "$cutcom") spec=$(realpath "$spec")
mkdir -p "$out/corpus" "$out/logs"
out=$(realpath "$out")
if (( tasks > 1 && (tasks % 2 == 0 || tasks % 3 == 0) )); then
  echo "slurm-campaign: note: $tasks tasks is not coprime to 6, so each task draws from some generators only (case k's generator is k mod 6); the campaign as a whole is the same" >&2
fi
per=$(( (cases + tasks - 1) / tasks ))  # cases per task: the campaign runs tasks * per cases

options=()
[[ -n "$partition" ]] && options+=(--partition="$partition")
[[ -n "$limit" ]] && options+=(--time="$limit")

cat >"$out/shard.sbatch" <<EOF
#!/usr/bin/env bash
#SBATCH --job-name=cutcom-certify-$seed
#SBATCH --array=0-$((tasks - 1))
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
#SBATCH --output=$out/logs/shard-%a.log
set -u
i=\$SLURM_ARRAY_TASK_ID
exec "$cutcom" certify --seed $seed --cases $per --shard \$i/$tasks --jobs 1 --budget $budget --no-progress \\
  --summary "$out/shard-\$i.json" --results "$out/results-\$i.jsonl" --corpus "$out/corpus"
EOF
cat >"$out/merge.sbatch" <<EOF
#!/usr/bin/env bash
#SBATCH --job-name=cutcom-merge-$seed
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
#SBATCH --output=$out/logs/merge.log
set -u
shards=()
for i in \$(seq 0 $((tasks - 1))); do
  if [[ -s "$out/shard-\$i.json" ]]; then shards+=("$out/shard-\$i.json"); else echo "shard \$i/$tasks left no summary (see logs/shard-\$i.log)"; missing=1; fi
done
"$cutcom" certify --merge "\${shards[@]}" --summary "$out/merged.json" --report "$out/certification.md" --spec "$spec"
status=\$?
[[ \${missing:-0} -eq 0 ]] || exit 3
exit \$status
EOF

array=$(sbatch --parsable "${options[@]}" "$out/shard.sbatch")
array=${array%%;*}
echo "campaign seed $seed: $((per * tasks)) cases in $tasks array tasks of $per, job $array; results in $out"
merge_options=("${options[@]}" --dependency=afterany:"$array")
if [[ $wait -eq 1 ]]; then
  status=0
  sbatch --wait "${merge_options[@]}" "$out/merge.sbatch" >/dev/null || status=$?
  tail -n 3 "$out/logs/merge.log"
  exit $status
fi
merge=$(sbatch --parsable "${merge_options[@]}" "$out/merge.sbatch")
echo "merge job ${merge%%;*} writes $out/certification.md when the array has run"
