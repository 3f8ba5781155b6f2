#!/bin/bash
# Embree on the shadow rays the Java renderer traces: a scratch worktree of HEAD with traced-rays.patch
# applied writes each real mesh's traced rays of one frame (one thread) to target/traced-rays/, then
# embree_bench --rays times Embree's packets and single rays on exactly those rays, and
# benchmark.RayReplay our single-ray walk on them.
# Usage: tools/embree/traced-rays.sh MODELS_FOLDER [MESH...]   (from the repository, after
#        mvn test-compile, mvn dependency:build-classpath -Dmdep.outputFile=cp.txt and tools/embree/build.sh)
set -e
MODELS=${1:-../shared/models}
shift || true
MESHES=${*:-cow fandisk rocker-arm teapot ogre}
REPO=$(pwd)
OUT=$REPO/target/traced-rays
PROBE=$OUT/probe
BENCH=$(dirname "$0")/embree_bench
mkdir -p "$OUT"
git worktree remove --force "$PROBE" 2>/dev/null || true
git worktree add --force --detach "$PROBE" HEAD >/dev/null
(cd "$PROBE" && git apply "$REPO/tools/embree/traced-rays.patch" && mvn -q -o compile)
for m in $MESHES; do
  [ -f "$MODELS/$m.obj" ] || { echo "$m: no $MODELS/$m.obj, skipped"; continue; }
  java -Xmx8g -DtracedRays="$OUT/$(basename "$m").bin" -cp "$PROBE/target/classes:target/test-classes:$(cat cp.txt)" \
    benchmark.Benchmark --scene "obj:$MODELS/$m.obj" --frames 1 --warmup 0 --threads 1 | grep -o '[0-9]* traced shadow rays/frame'
  for mode in packet single; do
    "$BENCH" --scene "obj:$MODELS/$m.obj" --mode $mode --threads 2 --warmup 3 --frames 7 \
      --rays "$OUT/$(basename "$m").bin" | grep RAYS
  done
  java -Xmx8g -cp "target/classes:target/test-classes:$(cat cp.txt)" benchmark.RayReplay --scene "obj:$MODELS/$m.obj" \
    --rays "$OUT/$(basename "$m").bin" | grep replayed
done
git worktree remove --force "$PROBE"
