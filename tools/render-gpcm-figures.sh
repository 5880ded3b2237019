#!/usr/bin/env bash
# Renders the generalized pinhole camera figures (thesis Figures 6-16 to 6-24) into docs/images/gpcm.
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/images/gpcm
mkdir -p "$out"
dotnet build -c Release src/RayTracer.App >/dev/null
rt() { dotnet src/RayTracer.App/bin/Release/net10.0/raytracer.dll render "$@" --seed 1; }

rt gpcm-rectangular -o "$out/rectangular-70.png"
for kind in cylindrical conic; do
  rt "gpcm-$kind" -o "$out/$kind-360.png"
  rt "gpcm-$kind" -o "$out/$kind-180.png" --camera "$kind:180" --width 480 --height 240
  rt "gpcm-$kind" -o "$out/$kind-90.png" --camera "$kind:90" --width 480 --height 240
done
rt gpcm-spherical -o "$out/spherical-360.png"
rt gpcm-spherical -o "$out/spherical-180.png" --camera spherical:180 --width 480 --height 240
rt gpcm-spherical -o "$out/spherical-90.png" --camera spherical:90 --width 480 --height 240
for degrees in 360 180 90; do
  rt gpcm-fisheye -o "$out/fisheye-$degrees.png" --camera "fisheye:$degrees"
done
# The "(a) layout and orientation" panels: each camera's surface drawn where the camera stands.
for kind in rectangular cylindrical conic spherical fisheye; do
  rt "gpcm-$kind-layout" -o "$out/$kind-layout.png"
done
