#!/bin/bash
# A real Slurm cluster on localhost (Debian's slurm-wlm and munge, ../docs/scale-out.md): the test
# starts munged, slurmctld and slurmd in a PID namespace of their own, submits the project's job
# script (scripts/scale-out/slurm-render.sh) as a real `sbatch --array`, requeues one task in the
# middle of its render, and checks that the frames that land are byte-identical to one whole run.
# Everything it starts dies with the namespace, also when the test fails.
#   slurm_cluster_test.sh FGC FGPLAY SOURCE_DIR WORK_DIR
set -euo pipefail
FGC=$1 FGPLAY=$2 SOURCE=$3 WORK=$4

fail() { echo "FAIL: $*" >&2; for f in "$WORK"/log/*.log "$WORK"/out/*.log; do [ -f "$f" ] && { echo "== $f"; tail -20 "$f"; }; done >&2; exit 1; }
for tool in munged mungekey slurmctld slurmd sbatch squeue scontrol sinfo unshare; do
  command -v "$tool" >/dev/null || fail "$tool is missing (Debian: slurm-wlm, munge; the README's test command installs them)"
done

rm -rf "$WORK"
mkdir -p "$WORK"/{munge,state,spool,log,out,whole}
chmod 755 "$WORK" "$WORK/munge"
NODE=$(hostname -s)
mkdir -p "$WORK/spool/$NODE"
mungekey -c -k "$WORK/munge/munge.key" 2>/dev/null
chmod 400 "$WORK/munge/munge.key"

# Ports away from a real cluster's; every path under the test's folder.
PORT_BASE=$((17000 + RANDOM % 2000))
cat >"$WORK/slurm.conf" <<EOF
ClusterName=fgtest
SlurmctldHost=$NODE(127.0.0.1)
SlurmctldPort=$PORT_BASE
SlurmdPort=$((PORT_BASE + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$WORK/munge/munge.socket,cred_expire=10
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool/%n
SlurmctldPidFile=$WORK/slurmctld.pid
SlurmdPidFile=$WORK/slurmd.pid
SlurmctldLogFile=$WORK/log/slurmctld.log
SlurmdLogFile=$WORK/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
JobRequeue=1
MailProg=/bin/true
NodeName=$NODE NodeAddr=127.0.0.1 CPUs=2 RealMemory=2000 State=UNKNOWN
PartitionName=render Nodes=$NODE Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$WORK/slurm.conf

# The daemons in their own PID namespace: one SIGKILL of it ends them and every job step
# (slurmstepd ignores SIGTERM and outlives slurmd otherwise).
unshare --pid --fork --kill-child --mount-proc bash -c "
  munged --key-file=$WORK/munge/munge.key --socket=$WORK/munge/munge.socket --pid-file=$WORK/munge/munged.pid \
         --log-file=$WORK/log/munged.log --seed-file=$WORK/munge/munged.seed
  slurmctld -D -f $WORK/slurm.conf >$WORK/log/slurmctld.out 2>&1 &
  slurmd -D -f $WORK/slurm.conf -N $NODE >$WORK/log/slurmd.out 2>&1 &
  wait" &
CLUSTER=$!
# The cluster dies with the script; a passing run then removes its folder (FG_KEEP_TEST_FILES=1 keeps it).
trap 'rc=$?; kill -KILL $CLUSTER 2>/dev/null || true; wait $CLUSTER 2>/dev/null || true
      [ $rc -eq 0 ] && [ "${FG_KEEP_TEST_FILES:-}" != 1 ] && rm -rf "$WORK"; exit $rc' EXIT

for _ in $(seq 1 120); do
  [ "$(sinfo -h -o %t 2>/dev/null | head -1)" = idle ] && break
  sleep 0.5
done
[ "$(sinfo -h -o %t 2>/dev/null | head -1)" = idle ] || fail "the node never became idle"
echo "cluster up: node $NODE idle"

"$FGC" compile "$SOURCE/tests/runtime/data/panorama_room.json" -o "$WORK/room.fgpack" >/dev/null
# 24 ODS frames over two array tasks (task 1 renders 12 to 23): long enough that a task is still
# rendering when it is requeued, short enough for CI.
cat >"$WORK/path.json" <<EOF
{"format": "fractograph-camera-path", "version": 1, "fps": 8, "keyframes": [
  {"time": 0.0, "position": [0, 0.2, 0.5], "target": [0, 0, -2]},
  {"time": 2.875, "position": [0.6, 0.3, -0.2], "target": [2, 0, 0]}]}
EOF
SETTINGS=(PROJECTION=ods SIZE=512x256 SUPERSAMPLE=2)

# The job script's own #SBATCH lines ask for a GPU, 4 CPUs and 16 GB: the command line overrides
# them for this one-node, two-CPU cluster, as a user would for theirs.
JOB=$(sbatch --parsable --array=0-1 --gres=none --cpus-per-task=1 --mem=200M --output="$WORK/out/task_%a.log" \
        --open-mode=append \
        --export=ALL,PACK="$WORK/room.fgpack",CAMERA="$WORK/path.json",OUT="$WORK/out",FGPLAY="$FGPLAY",TMPDIR="$WORK","$(IFS=,; echo "${SETTINGS[*]}")" \
        "$SOURCE/scripts/scale-out/slurm-render.sh") || fail "sbatch refused the job script"
echo "submitted array job $JOB"

# Requeue task 1 once it has written its first frame but not its last: Slurm kills it and runs it
# again, and the rerun (--resume in the script) renders only what the first run did not finish.
requeued=0
for _ in $(seq 1 1500); do
  state=$(squeue -h -j "${JOB}_1" -o %T 2>/dev/null || true)
  if [ "$requeued" = 0 ] && [ "$state" = RUNNING ] && [ -f "$WORK/out/frame_000012.png" ] \
     && [ ! -f "$WORK/out/frame_000023.png" ]; then
    scontrol requeue "${JOB}_1"
    scontrol update JobId="${JOB}_1" StartTime=now >/dev/null 2>&1 || true
    requeued=1
    echo "requeued task 1 with $(ls "$WORK"/out/frame_*.png | wc -l) frames of 24 on disk"
  fi
  [ -z "$(squeue -h -j "$JOB" 2>/dev/null)" ] && break
  sleep 0.2
done
[ -z "$(squeue -h -j "$JOB" 2>/dev/null)" ] || fail "the array did not finish"
[ "$requeued" = 1 ] || fail "task 1 finished before it could be requeued"
grep -E "^rendered [0-9]+ frames, skipped [1-9][0-9]* already done" "$WORK/out/task_1.log" \
  || fail "task 1's rerun after the requeue did not resume: $(grep '^rendered' "$WORK/out/task_1.log")"

MESA_SHADER_CACHE_DIR=$WORK/cache "$FGPLAY" render "$WORK/room.fgpack" --path "$WORK/path.json" --projection ods \
  --size 512x256 --supersample 2 --out "$WORK/whole" --no-progress >/dev/null
count=0
for f in "$WORK"/whole/frame_*.png; do
  name=$(basename "$f")
  cmp -s "$f" "$WORK/out/$name" || fail "$name differs between the cluster's array and one whole run"
  count=$((count + 1))
done
[ "$count" = 24 ] || fail "expected 24 frames, the whole run wrote $count"
[ "$(ls "$WORK"/out/frame_*.png | wc -l)" = 24 ] || fail "the array wrote $(ls "$WORK"/out/frame_*.png | wc -l) frames, not 24"
echo "PASS: array job $JOB on a real slurmctld/slurmd, task 1 requeued mid-render; 24 frames identical to one run"
