#!/bin/sh
# Regenerates every scene in scenes/ from the project's own tools.
set -eu
cd "$(dirname "$0")/.."
python3 tools/make_cornell_box.py scenes/cornell-box.gltf
for light in point sphere spot rect-spot directional; do
    python3 tools/make_cornell_box.py --light "$light"
done
python3 tools/make_cornell_box.py --variant glass-mirror
python3 tools/make_cornell_box.py --variant features
python3 tools/make_cornell_box.py --variant instanced
python3 tools/make_sky_scene.py scenes
python3 tools/make_material_spheres.py scenes
python3 tools/make_textured_scene.py scenes
