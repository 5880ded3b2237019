#!/usr/bin/env bash
# Primary-ray cost of the generalized pinhole cameras against the hand cameras
# (bench/results/gpcm-rays.md). BenchmarkDotNet runs in process here, so each pair
# gets a process of its own: the JIT's profile of a camera's GetRay would otherwise
# mix every camera measured before it in the same process.
set -euo pipefail
cd "$(dirname "$0")/.."
dotnet build -c Release bench/GMac.Benchmarks >/dev/null
run() { dotnet run -c Release --no-build --project bench/GMac.Benchmarks -- --filter "$@" --iterationCount 15 --warmupCount 3 | grep -E '^\| '; }
run '*PrimaryRay*.Pinhole' '*PrimaryRay*.RectangularGpcm'
run '*PrimaryRay*.SphericalHand' '*PrimaryRay*.SphericalGpcm'
run '*PrimaryRay*.FisheyeHand' '*PrimaryRay*.FisheyeGpcm'
run '*PrimaryRay*.CylindricalGpcm' '*PrimaryRay*.ConicGpcm'
run '*PrimaryRay*Cascade'
