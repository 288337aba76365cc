#!/bin/sh
# Renders the committed scenes for the gallery that the README and docs/scenes.md show:
# 384x384, filmic tone curve, 256 samples per pixel (1024 where glass, caustics or light
# from a punctual spot need them), written as JPEG (quality 85) into docs/gallery/, 10 to
# 30 KB an image.
#
#   tools/render_gallery.sh [BUILD_DIR] [OUT_DIR] [SCENE...]
#
# BUILD_DIR holds pathcl (default build; build it first, e.g. with tools/render_default.sh),
# OUT_DIR is docs/gallery by default, and SCENE names scenes/SCENE.gltf (default: all of the
# gallery's). GALLERY_SIZE and GALLERY_SPP_SCALE (a factor on every scene's spp) make a
# quicker or a finer gallery. The PNG's conversion to JPEG is OpenImageIO's oiiotool
# (Debian's openimageio-tools, installed when missing). Each image is written under a
# temporary name in OUT_DIR and renamed, so an existing image is replaced only by a
# complete one.
set -eu
cd "$(dirname "$0")/.."
BUILD=${1:-build}
OUT=${2:-docs/gallery}
[ $# -gt 2 ] && shift 2 || set --
SIZE=${GALLERY_SIZE:-384}
SCALE=${GALLERY_SPP_SCALE:-1}
QUALITY=85

[ -x "$BUILD/pathcl" ] || { echo "render_gallery: no $BUILD/pathcl; build it first" >&2; exit 2; }
if ! command -v oiiotool >/dev/null 2>&1; then
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO=sudo
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends openimageio-tools
fi
mkdir -p "$OUT"
tmp=$(mktemp -d "$OUT/gallery.tmp.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM

# scene name, spp, then any render options it needs.
gallery()
{
    name=$1 spp=$(($2 * SCALE))
    shift 2
    start=$(date +%s)
    "$BUILD/pathcl" render "scenes/$name.gltf" -o "$tmp/$name.png" --width "$SIZE" --height "$SIZE" \
        --spp "$spp" --tone filmic --quiet "$@"
    oiiotool "$tmp/$name.png" --compression "jpeg:$QUALITY" -o "$tmp/$name.jpg"
    mv "$tmp/$name.jpg" "$OUT/$name.jpg"
    echo "render_gallery: $OUT/$name.jpg, $spp spp, $(($(date +%s) - start)) s, $(wc -c <"$OUT/$name.jpg") bytes"
}

SCENES=${*:-"cornell-box cornell-box-glass-mirror cornell-box-features cornell-box-instanced cornell-box-rect-spot
  cornell-box-sphere material-spheres textured sky-spheres sky-glass"}
for scene in $SCENES; do
    case $scene in
    cornell-box-glass-mirror | cornell-box-features | cornell-box-rect-spot | material-spheres | sky-glass)
        gallery "$scene" 1024 ;;
    *) gallery "$scene" 256 ;;
    esac
done
