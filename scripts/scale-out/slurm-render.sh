#!/bin/bash
# Render a camera path as a Slurm job array (docs/scale-out.md). Each array task renders its shard
# of the frame range into shared storage; submitting the same script again renders only frames
# that are missing or fail verification (--resume), so re-runs and requeues are idempotent.
#
#   sbatch --array=0-63%16 scripts/scale-out/slurm-render.sh      (64 shards, 16 at a time)
#
# Settings come from the environment (sbatch --export=ALL,PACK=...,OUT=...):
#   PACK        the shader pack on shared storage               (required)
#   CAMERA      the camera path JSON (docs/camera-path.md)      (required)
#   OUT         output folder on shared storage                 (required)
#   FRAMES      frame range A:B of the path                     (default: the whole path)
#   PROJECTION  perspective | equirect | ods                    (default: ods)
#   SIZE        per-eye size WxH                                (default: 4096x2048)
#   SUPERSAMPLE samples per pixel along each axis               (default: 2)
#   FGPLAY      the fgplay binary                               (default: fgplay on PATH)
#SBATCH --job-name=fg-render
#SBATCH --array=0-15
#SBATCH --gres=gpu:1
#SBATCH --cpus-per-task=4
#SBATCH --mem=16G
#SBATCH --time=04:00:00
#SBATCH --requeue
#SBATCH --output=fg-render_%A_%a.log
set -euo pipefail

: "${PACK:?set PACK to the .fgpack on shared storage}"
: "${CAMERA:?set CAMERA to the camera path JSON}"
: "${OUT:?set OUT to the output folder on shared storage}"
FGPLAY=${FGPLAY:-fgplay}

# The shard is this task's place in the array, whatever the array's first index and throttle.
index=$(( SLURM_ARRAY_TASK_ID - ${SLURM_ARRAY_TASK_MIN:-0} ))
count=$(( ${SLURM_ARRAY_TASK_MAX:-$SLURM_ARRAY_TASK_ID} - ${SLURM_ARRAY_TASK_MIN:-0} + 1 ))

# Compiled shaders are cached per node, not on shared storage (many writers, no gain).
export MESA_SHADER_CACHE_DIR=${TMPDIR:-/tmp}/fg-shader-cache-${SLURM_JOB_ID:-local}

mkdir -p "$OUT"
exec "$FGPLAY" render "$PACK" --path "$CAMERA" --frames "${FRAMES:-:}" --shard "$index/$count" \
    --projection "${PROJECTION:-ods}" --size "${SIZE:-4096x2048}" --supersample "${SUPERSAMPLE:-2}" \
    --out "$OUT" --resume --no-progress
