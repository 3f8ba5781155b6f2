#!/bin/bash
# Takes turns on the real meshes: Embree with 16-ray packets, Embree one ray at a time, then the Java
# benchmark, for ROUNDS rounds; prints each run's median s/frame.
# Usage: tools/embree/compare.sh ROUNDS MODELS_FOLDER   (from the repository, after mvn test-compile,
#        mvn dependency:build-classpath -Dmdep.outputFile=cp.txt and tools/embree/build.sh)
set -e
ROUNDS=${1:-3}
MODELS=${2:-../shared/models}
BENCH=$(dirname "$0")/embree_bench
CP=target/classes:target/test-classes:$(cat cp.txt)
for r in $(seq "$ROUNDS"); do
  for s in cow fandisk rocker-arm teapot ogre suzanne; do
    scene=obj:$MODELS/$s.obj
    [ -f "$MODELS/$s.obj" ] || { echo "$s: no $MODELS/$s.obj, skipped"; continue; }
    packet=$("$BENCH" --scene "$scene" --mode packet | grep -o 'median_s=[0-9.]*' | cut -d= -f2)
    single=$("$BENCH" --scene "$scene" --mode single | grep -o 'median_s=[0-9.]*' | cut -d= -f2)
    java=$(java -Xmx8g -cp "$CP" benchmark.Benchmark --scene "$scene" --frames 5 --warmup 6 --threads 2 \
      | grep -o 'median [0-9.]* s/frame' | cut -d' ' -f2)
    echo "$s: Embree packets $packet, Embree single rays $single, ours $java s/frame"
  done
done
