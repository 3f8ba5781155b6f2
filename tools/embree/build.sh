#!/bin/sh
# Builds embree_bench against Debian's libembree-dev (Embree 3).
set -e
cd "$(dirname "$0")"
g++ -O3 -march=native -std=c++17 -Wall -o embree_bench embree_bench.cpp -lembree3 -pthread
