#!/usr/bin/env bash
# A single-node Slurm on localhost runs an `hfshade tiles` plan as a job
# array (issue 40 item 2; tools/slurm/hfshade_tiles.sbatch): munged,
# slurmctld and slurmd started in a temporary folder with a configuration
# of their own (no systemd, no /etc change), the Jacksboro DEM (a VRT
# georeferencing data/jacksboro.png in UTM 16N, 83 m cells) planned in
# 12 jobs of svf (CPU reference), the array submitted, waited for, merged,
# and the mosaic compared byte for byte with the same plan's jobs run one
# by one without Slurm.  Skips (exit 77, the reason on its SKIP line) where
# Slurm cannot start: slurm-wlm or munge not installed (tools/install-deps.sh
# installs both), not root (the daemons' users), or the daemons not up
# within 30 s.  Prints the array's logs.
# usage: tests/slurm_tiles.sh HFSHADE SOURCE_DIR
set -uo pipefail
H=$(realpath "$1")
SRC=$(realpath "$2")
skip() { echo "SKIP: slurm_tiles: $*"; exit 77; }
for t in munged slurmctld slurmd sbatch squeue scontrol; do
    command -v "$t" >/dev/null || skip "$t not found (Debian slurm-wlm and munge; tools/install-deps.sh)"
done
[ "$(id -u)" -eq 0 ] || skip "not root: the test starts munged, slurmctld and slurmd as root"
D=$(mktemp -d /tmp/hfs_slurm_XXXXXX)
chmod 755 "$D"
cleanup() {
    SLURM_CONF=$D/slurm.conf scontrol shutdown >/dev/null 2>&1
    for p in "$D/slurmd.pid" "$D/slurmctld.pid" "$D/munged.pid"; do
        [ -f "$p" ] && kill "$(cat "$p")" 2>/dev/null
    done
    sleep 0.5
    [ -n "${HFS_TEST_KEEP:-}" ] && echo "kept $D" || rm -rf "$D"
}
trap cleanup EXIT
mkdir -p "$D/state" "$D/spool"
munged --force --socket="$D/munge.socket" --pid-file="$D/munged.pid" --log-file="$D/munged.log" \
    --seed-file="$D/munge.seed" || skip "munged did not start (no /etc/munge/munge.key?)"
node=$(hostname)
cat >"$D/slurm.conf" <<CONF
ClusterName=hfstest
SlurmctldHost=$node
SlurmUser=root
SlurmdUser=root
SlurmctldPort=16917
SlurmdPort=16918
AuthType=auth/munge
AuthInfo=socket=$D/munge.socket
CredType=cred/munge
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/slurmctld.log
SlurmdLogFile=$D/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
# batch_sched_delay=0: start each array task at once (the default
# delay started one task every 3 s: 21 s of this test, now 11 s).
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$node CPUs=$(nproc) State=UNKNOWN
PartitionName=hfs Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$D/slurm.conf
slurmctld -c || skip "slurmctld did not start: $(tail -1 "$D/slurmctld.log" 2>/dev/null)"
slurmd || skip "slurmd did not start: $(tail -1 "$D/slurmd.log" 2>/dev/null)"
up=0
for _ in $(seq 60); do
    sinfo -h -o %t 2>/dev/null | grep -q idle && { up=1; break; }
    sleep 0.5
done
[ $up -eq 1 ] || skip "the node did not come up within 30 s: $(tail -1 "$D/slurmctld.log")"

cat >"$D/jb.vrt" <<VRT
<VRTDataset rasterXSize="403" rasterYSize="344">
  <SRS>EPSG:32616</SRS>
  <GeoTransform>733000, 83, 0, 4029000, 0, -83</GeoTransform>
  <VRTRasterBand dataType="Float32" band="1">
    <SimpleSource><SourceFilename>$SRC/data/jacksboro.png</SourceFilename><SourceBand>1</SourceBand></SimpleSource>
  </VRTRasterBand>
</VRTDataset>
VRT
fail() { echo "FAIL: slurm_tiles: $*"; exit 1; }
opts=(--product svf --tile 128 --backend cpu --radius 1500 --directions 8)
"$H" tiles plan "$D/jb.vrt" "${opts[@]}" -o "$D/plan" || fail "plan"
"$H" tiles plan "$D/jb.vrt" "${opts[@]}" -o "$D/local" || fail "plan (local)"
n=$(wc -l <"$D/plan/jobs")
jid=$(cd "$D" && HFSHADE=$H sbatch --parsable --array=1-"$n" --cpus-per-task=1 \
    "$SRC/tools/slurm/hfshade_tiles.sbatch" "$D/plan/manifest") || fail "sbatch"
echo "submitted array $jid of $n tasks"
for _ in $(seq 600); do
    [ "$(squeue -h -j "$jid" 2>/dev/null | wc -l)" -eq 0 ] && break
    sleep 0.5
done
[ "$(squeue -h -j "$jid" | wc -l)" -eq 0 ] || fail "the array did not finish in 300 s"
for f in "$D"/hfshade-tiles-*.log; do echo "== $(basename "$f"): $(cat "$f")"; done
"$H" tiles merge "$D/plan" -o "$D/slurm.tif" || fail "merge after the array"
for k in $(seq "$n"); do "$H" tiles run "$D/local/manifest" "$k" 2>/dev/null || fail "local job $k"; done
"$H" tiles merge "$D/local" -o "$D/local.tif" || fail "merge (local)"
cmp "$D/slurm.tif" "$D/local.tif" || fail "the array's mosaic differs from the local run's"
echo "slurm_tiles: $n array tasks merged, byte for byte the local run's mosaic"
