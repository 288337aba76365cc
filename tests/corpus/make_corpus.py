#!/usr/bin/env python3
"""Writes the hostile-input corpus into tests/corpus/files/ and its manifest
tests/corpus/expected.tsv. Standard library only; deterministic (run it again and git
shows no change). tests/corpus_test.sh runs pathcl on every case of the manifest.

Every file is small (the largest, the 100,000-deep JSON nestings, are 200 to 600 KB; the
32 KB PNG that inflates to a 1 GiB texture is built with zlib here). The 100,000-deep node
chain (about 2 MB of JSON) and every FIFO are made by the runner at test time instead.

The valid parts of every case come from one minimal renderable scene: a camera at
(0, 0, 3) looking down -Z at an emissive, exactly Lambertian triangle (the Cornell box's
kernel variant: area lights only), with TEXCOORD_0 so that any case can add a texture.

Manifest columns (tab-separated; '-' is empty):
  name     the case
  file     the scene, relative to files/ (the runner renders a copy of files/); '-': args
           is the whole command line after `pathcl` (merge, converge), run as it is
  args     extra render arguments; {CWD} is the run's working directory, {FILES} the
           copied files/ directory, {SCENE} the scene's path, {RO} a directory nobody can
           write into. Without -o the runner adds -o out.png (in {CWD}); without --width,
           --height or --spp it adds --width 16, --height 16 or --spp 1.
  expect   error: exit 2, exactly one stderr line "pathcl: error: ..." naming the file
           (or `names`), nothing written; renders: exit 0 and the output written;
           any: either (a valid but absurd input, where a limit is as right as a render)
  setup    comma-separated actions of the runner before the run:
             mkfifo:REL          a FIFO at files/REL
             cwd:SRC=DEST        copy files/SRC to {CWD}/DEST
             mkdir:REL           a directory {CWD}/REL
             existing-output     {CWD}/out.png exists; it must stay byte-identical
             chain:N:REL         files/REL: an N-deep node chain ending at the triangle
             sparse:REL:SIZE     files/REL: a sparse file of SIZE bytes (truncate -s)
             partial:REL:FIRST:COUNT  files/REL: samples FIRST..FIRST+COUNT-1 of the 4x4,
                                 32-spp render of valid.gltf in batches of 16 (made by pathcl)
             replace:REL|OLD|NEW files/REL with bytes OLD replaced by NEW, once, of the same
                                 length (Python escapes such as \\x00 allowed)
  names    what the error line must contain ('-': the scene file's name; A|B: A or B)
  what     a short description
"""

import base64
import json
import os
import shutil
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
FILES = os.path.join(HERE, "files")

CASES = []  # (name, file, args, expect, setup, names, description)
CLI_CASES = 0


def case(name, file, expect, what, args="-", setup="-", names="-"):
    assert "\t" not in what and "\t" not in args
    assert not any(c[0] == name for c in CASES), name
    CASES.append((name, file, args, expect, setup, names, what))


def write(rel, data):
    path = os.path.join(FILES, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    if isinstance(data, str):
        data = data.encode("utf-8")
    with open(path, "wb") as f:
        f.write(data)
    return rel


# ---------------------------------------------------------------------------------------
# The minimal scene
# ---------------------------------------------------------------------------------------

POSITIONS = [(-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (0.0, 1.0, 0.0)]
TEXCOORDS = [(0.0, 1.0), (1.0, 1.0), (0.5, 0.0)]


def geometry():
    """68 bytes: POSITION (36), TEXCOORD_0 (24), u16 indices (6) and 2 bytes of padding."""
    data = b"".join(struct.pack("<3f", *p) for p in POSITIONS)
    data += b"".join(struct.pack("<2f", *t) for t in TEXCOORDS)
    data += struct.pack("<3H", 0, 1, 2) + b"\0\0"
    assert len(data) == 68
    return data


GEOMETRY = geometry()
DATA_URI = "data:application/octet-stream;base64," + base64.b64encode(GEOMETRY).decode("ascii")


def base(buffer_uri=DATA_URI):
    """The minimal renderable scene as a dict; buffer_uri None: a GLB's BIN chunk."""
    buffer = {"byteLength": len(GEOMETRY)}
    if buffer_uri is not None:
        buffer["uri"] = buffer_uri
    return {
        "asset": {"version": "2.0", "generator": "pathcl tests/corpus/make_corpus.py"},
        "extensionsUsed": ["KHR_materials_specular"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"name": "triangle", "mesh": 0},
            {"name": "camera", "camera": 0, "translation": [0.0, 0.0, 3.0]},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "aspectRatio": 1.0, "znear": 0.01}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2,
                                    "material": 0, "mode": 4}]}],
        "materials": [{
            "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 0.0,
                                     "roughnessFactor": 1.0},
            "emissiveFactor": [1.0, 1.0, 1.0],
            "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}},
        }],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [-1.0, -1.0, 0.0], "max": [1.0, 1.0, 0.0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36},
            {"buffer": 0, "byteOffset": 36, "byteLength": 24},
            {"buffer": 0, "byteOffset": 60, "byteLength": 6},
        ],
        "buffers": [buffer],
    }


def dump(model):
    return json.dumps(model, indent=1, allow_nan=False) + "\n"


def gltf(rel, model):
    return write(rel, dump(model))


def model_case(rel, name, expect, what, model, raw=None):
    """Writes `model` as rel (with one number's text replaced by raw = (old, new), for
    values JSON cannot hold) and lists it as a case."""
    text = dump(model)
    if raw:
        text = replace_number(text, *raw)
    write(rel, text)
    case(name, rel, expect, what)


def with_light(light, node_extra=None):
    m = base()
    m["extensionsUsed"].append("KHR_lights_punctual")
    m["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
    node = {"name": "light", "translation": [0.0, 0.0, 1.0], "extensions": {"KHR_lights_punctual": {"light": 0}}}
    node.update(node_extra or {})
    m["nodes"].append(node)
    m["scenes"][0]["nodes"].append(2)
    return m


def with_texture(image):
    m = base()
    m["images"] = [image]
    m["textures"] = [{"source": 0}]
    m["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    return m


def with_environment(env):
    m = base()
    m["scenes"][0]["extras"] = {"environment": env}
    return m


def replace_number(text, old, new):
    """Puts a token JSON cannot hold (NaN, 1e999, a 20-digit integer) in place of a
    unique placeholder number."""
    assert text.count(old) == 1, old
    return text.replace(old, new)


# ---------------------------------------------------------------------------------------
# Binary formats
# ---------------------------------------------------------------------------------------


def glb(json_bytes, bin_bytes, magic=b"glTF", version=2, total=None, json_len=None, json_type=b"JSON",
        bin_len=None, bin_type=b"BIN\0", cut=None):
    """A GLB container; every header field can be overridden, and `cut` truncates."""
    json_bytes += b" " * (-len(json_bytes) % 4)
    body = struct.pack("<I", len(json_bytes) if json_len is None else json_len) + json_type + json_bytes
    if bin_bytes is not None:
        bin_bytes += b"\0" * (-len(bin_bytes) % 4)
        body += struct.pack("<I", len(bin_bytes) if bin_len is None else bin_len) + bin_type + bin_bytes
    length = 12 + len(body) if total is None else total
    data = magic + struct.pack("<II", version, length) + body
    return data if cut is None else data[:cut]


def glb_json(model):
    return json.dumps(model, separators=(",", ":"), allow_nan=False).encode("utf-8")


def png_chunk(kind, payload, crc=None):
    c = zlib.crc32(kind + payload) & 0xFFFFFFFF if crc is None else crc
    return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", c)


PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png(width, height, rows, bit_depth=8, colour_type=2, ihdr_crc=None, idat_crc=None, idat=None, iend=True):
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    compressed = zlib.compress(rows, 9) if idat is None else idat
    data = PNG_SIGNATURE + png_chunk(b"IHDR", ihdr, ihdr_crc) + png_chunk(b"IDAT", compressed, idat_crc)
    return data + (png_chunk(b"IEND", b"") if iend else b"")


def rgb_rows(width, height, texel=(200, 120, 40)):
    row = b"\0" + bytes(texel) * width
    return row * height


VALID_PNG = png(2, 2, rgb_rows(2, 2))


def hdr(width, height, pixels=None, header_extra=b""):
    """Radiance RGBE, flat (uncompressed) scanlines."""
    head = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n" + header_extra + b"\n"
    head += b"-Y %d +X %d\n" % (height, width)
    if pixels is None:
        pixels = bytes((128, 128, 128, 129)) * (width * height)  # (1, 1, 1)
    return head + pixels


def exr(width, height, x_min=0, y_min=0, x_max=None, y_max=None, cut=None, offsets=None, pixel_type=2, extra=b""):
    """A scanline OpenEXR file: channels B, G, R as FLOAT (or pixel_type), no compression,
    one line per block; `extra`: more attributes, as bytes, at the end of the header."""
    x_max = x_min + width - 1 if x_max is None else x_max
    y_max = y_min + height - 1 if y_max is None else y_max

    def attribute(name, kind, value):
        return name + b"\0" + kind + b"\0" + struct.pack("<i", len(value)) + value

    chlist = b"".join(c + b"\0" + struct.pack("<iB3xii", pixel_type, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    header = struct.pack("<Ii", 20000630, 2)
    header += attribute(b"channels", b"chlist", chlist)
    header += attribute(b"compression", b"compression", b"\0")
    header += attribute(b"dataWindow", b"box2i", struct.pack("<4i", x_min, y_min, x_max, y_max))
    header += attribute(b"displayWindow", b"box2i", struct.pack("<4i", x_min, y_min, x_max, y_max))
    header += attribute(b"lineOrder", b"lineOrder", b"\0")
    header += attribute(b"pixelAspectRatio", b"float", struct.pack("<f", 1.0))
    header += attribute(b"screenWindowCenter", b"v2f", struct.pack("<2f", 0.0, 0.0))
    header += attribute(b"screenWindowWidth", b"float", struct.pack("<f", 1.0))
    header += extra + b"\0"
    lines = height if offsets is None else offsets
    table_end = len(header) + 8 * lines
    line_bytes = 8 + 3 * 4 * width
    table = b"".join(struct.pack("<Q", table_end + y * line_bytes) for y in range(lines))
    blocks = b""
    if offsets is None:
        for y in range(height):
            blocks += struct.pack("<ii", y_min + y, 3 * 4 * width)
            for channel in (0.25, 0.5, 1.0):  # B, G, R
                blocks += struct.pack("<f", channel) * width
    data = header + table + blocks
    return data if cut is None else data[:cut]


# ---------------------------------------------------------------------------------------
# The cases
# ---------------------------------------------------------------------------------------


def valid_scenes():
    gltf("valid.gltf", base())
    case("valid-gltf", "valid.gltf", "renders", "the minimal scene itself (a data: URI buffer)")
    write("valid.glb", glb(glb_json(base(None)), GEOMETRY))
    case("valid-glb", "valid.glb", "renders", "the minimal scene as a GLB")
    write("shared/triangle.bin", GEOMETRY)
    gltf("valid-external-bin.gltf", base("shared/triangle.bin"))
    case("valid-external-bin", "valid-external-bin.gltf", "renders", "the buffer in a .bin file in a subdirectory")
    write("shared/texture.png", VALID_PNG)
    gltf("valid-texture.gltf", with_texture({"uri": "shared/texture.png"}))
    case("valid-texture", "valid-texture.gltf", "renders", "a 2x2 PNG base-colour texture")
    write("env/valid.hdr", hdr(8, 4))
    gltf("valid-env-hdr.gltf", with_environment({"uri": "env/valid.hdr", "strength": 0.5}))
    case("valid-env-hdr", "valid-env-hdr.gltf", "renders", "an 8x4 Radiance HDR environment map in scene extras")
    write("env/valid.exr", exr(8, 4))
    gltf("valid-env-exr.gltf", with_environment({"uri": "env/valid.exr"}))
    case("valid-env-exr", "valid-env-exr.gltf", "renders", "an 8x4 OpenEXR environment map in scene extras")
    m = base()
    m["nodes"][0]["scale"] = [0.0, 0.0, 0.0]
    gltf("valid-zero-scale.gltf", m)
    case("valid-zero-scale", "valid-zero-scale.gltf", "renders",
         "a singular (zero-scale) mesh node: its triangle is degenerate and dropped, a black image")
    # A 1,000-deep chain is committed; the 100,000-deep one is made at test time.
    gltf("valid-chain-1000.gltf", chain_model(1000))
    case("valid-chain-1000", "valid-chain-1000.gltf", "renders", "a 1,000-deep node chain ending at the triangle")
    # The runner's template: compact JSON, one line, with "@NODES@" for the node objects
    # and "@CAMERA@" for the camera node's index.
    m = base()
    m["nodes"] = "@NODES@"
    m["scenes"][0]["nodes"] = [0, "@CAMERA@"]
    write("generated/chain-template.json", json.dumps(m, separators=(",", ":")) + "\n")
    case("valid-chain-100000", "generated/chain-100000.gltf", "renders",
         "a 100,000-deep node chain ending at the triangle (about 2 MB, made by the runner)",
         setup="chain:100000:generated/chain-100000.gltf")


def chain_model(depth):
    """Node 0 -> 1 -> ... -> depth-1, which holds the mesh; the camera is the last node.
    (The runner writes the same structure with awk for the 100,000-deep case.)"""
    m = base()
    nodes = [{"children": [i + 1]} for i in range(depth - 1)] + [{"mesh": 0}]
    nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 0.0, 3.0]})
    m["nodes"] = nodes
    m["scenes"][0]["nodes"] = [0, depth]
    return m


def json_cases():
    text = dump(base())
    write("json/truncated.gltf", text[: len(text) // 2])
    case("json-truncated", "json/truncated.gltf", "error", "the minimal scene cut in half")
    write("json/empty.gltf", b"")
    case("json-empty", "json/empty.gltf", "error", "an empty file")
    write("json/binary-garbage.gltf", bytes((i * 37 + 11) % 256 for i in range(512)))
    case("json-binary-garbage", "json/binary-garbage.gltf", "error", "512 bytes of binary garbage")
    write("json/array-root.gltf", "[]\n")
    case("json-array-root", "json/array-root.gltf", "error", "valid JSON whose root is an array")
    write("json/no-asset.gltf", '{"scenes": [{"nodes": []}], "scene": 0}\n')
    case("json-no-asset", "json/no-asset.gltf", "error", "no asset object (required)")
    write("json/nan-literal.gltf", replace_number(text, "0.9", "NaN"))
    case("json-nan-literal", "json/nan-literal.gltf", "error", "yfov written as the non-JSON token NaN")
    write("json/glb-named-gltf.gltf", glb(glb_json(base(None)), GEOMETRY))
    case("json-glb-named-gltf", "json/glb-named-gltf.gltf", "any",
         "a valid GLB in a .gltf file (refused as JSON, or recognised by its magic)")
    depth = 100000
    nested = "[" * depth + "]" * depth
    write("json/deep-array-extras.gltf", replace_number(dump(with_extras_placeholder()), "424242", nested))
    case("json-deep-array-extras", "json/deep-array-extras.gltf", "error",
         "100,000 nested arrays in scene extras (a recursive parser overflows its stack)")
    nested = '{"a":' * depth + "1" + "}" * depth
    write("json/deep-object-extras.gltf", replace_number(dump(with_extras_placeholder()), "424242", nested))
    case("json-deep-object-extras", "json/deep-object-extras.gltf", "error",
         "100,000 nested objects in scene extras")
    m = base()
    m["unknownProperty"] = 424242
    nested = "[" * depth + "]" * depth
    write("json/deep-unknown-property.gltf", replace_number(dump(m), "424242", nested))
    case("json-deep-unknown-property", "json/deep-unknown-property.gltf", "any",
         "100,000 nested arrays in an unknown top-level property (ignored, or refused by a nesting limit)")
    m = base(None)
    m["scenes"][0]["extras"] = 424242
    write("json/deep-extras.glb", glb(replace_number(glb_json(m).decode(), "424242", "[" * depth + "]" * depth)
                                       .encode(), GEOMETRY))
    case("glb-deep-json", "json/deep-extras.glb", "error", "a GLB whose JSON chunk nests 100,000 arrays")


def with_extras_placeholder():
    m = base()
    m["scenes"][0]["extras"] = 424242
    return m


def glb_cases():
    j, b = glb_json(base(None)), GEOMETRY
    full = glb(j, b)
    write("glb/truncated-header.glb", full[:6])
    case("glb-truncated-header", "glb/truncated-header.glb", "error", "6 bytes: half a GLB header")
    write("glb/truncated-half.glb", full[: len(full) // 2])
    case("glb-truncated-half", "glb/truncated-half.glb", "error", "a valid GLB cut in half (inside the JSON chunk)")
    write("glb/truncated-bin.glb", full[:-20])
    case("glb-truncated-bin", "glb/truncated-bin.glb", "error", "a valid GLB missing the last 20 bytes of its BIN chunk")
    write("glb/bad-magic.glb", glb(j, b, magic=b"glTX"))
    case("glb-bad-magic", "glb/bad-magic.glb", "error", "magic 'glTX'")
    write("glb/version-1.glb", glb(j, b, version=1))
    case("glb-version-1", "glb/version-1.glb", "error", "GLB container version 1")
    write("glb/length-past-end.glb", glb(j, b, total=len(full) + 4096))
    case("glb-length-past-end", "glb/length-past-end.glb", "error", "header length 4 KB past the end of the file")
    write("glb/length-too-small.glb", glb(j, b, total=20))
    case("glb-length-too-small", "glb/length-too-small.glb", "error", "header length 20, shorter than its chunks")
    write("glb/json-length-past-end.glb", glb(j, b, json_len=len(j) + 4096))
    case("glb-json-length-past-end", "glb/json-length-past-end.glb", "error",
         "JSON chunk length 4 KB past the end of the file")
    write("glb/json-length-huge.glb", glb(j, b, json_len=0xFFFFFFF0))
    case("glb-json-length-huge", "glb/json-length-huge.glb", "error", "JSON chunk length 0xFFFFFFF0")
    write("glb/json-length-zero.glb", glb(j, b, json_len=0))
    case("glb-json-length-zero", "glb/json-length-zero.glb", "error", "JSON chunk length 0")
    write("glb/json-chunk-type-bin.glb", glb(j, b, json_type=b"BIN\0"))
    case("glb-json-chunk-type-bin", "glb/json-chunk-type-bin.glb", "error", "first chunk typed BIN, not JSON")
    # BIN chunk 8 bytes longer than what is left; the header's total length matches the file.
    bin_padded = len(b) + (-len(b) % 4)
    write("glb/bin-length-8-past-end.glb", glb(j, b, bin_len=bin_padded + 8))
    case("glb-bin-length-8-past-end", "glb/bin-length-8-past-end.glb", "error",
         "BIN chunk length runs 8 bytes past the end of the file (header length consistent)")
    data = glb(j, b, bin_len=bin_padded + 8)
    data = data[:8] + struct.pack("<I", len(data) + 8) + data[12:]
    write("glb/bin-length-and-total-8-past-end.glb", data)
    case("glb-bin-length-and-total-8-past-end", "glb/bin-length-and-total-8-past-end.glb", "error",
         "BIN chunk length and header length both 8 bytes past the end")
    write("glb/bin-length-huge.glb", glb(j, b, bin_len=0xFFFFFFFF))
    case("glb-bin-length-huge", "glb/bin-length-huge.glb", "error", "BIN chunk length 0xFFFFFFFF")
    write("glb/bin-shorter-than-buffer.glb", glb(j, b[:40]))
    case("glb-bin-shorter-than-buffer", "glb/bin-shorter-than-buffer.glb", "error",
         "buffer byteLength 68 but a 40-byte BIN chunk")
    write("glb/no-bin-chunk.glb", glb(j, None))
    case("glb-no-bin-chunk", "glb/no-bin-chunk.glb", "error", "buffer 0 has no uri and there is no BIN chunk")
    m = base(None)
    m["images"] = [{"bufferView": 3, "mimeType": "image/png"}]
    m["textures"] = [{"source": 0}]
    m["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    m["bufferViews"].append({"buffer": 0, "byteOffset": 64, "byteLength": 4096})
    write("glb/image-view-past-buffer.glb", glb(glb_json(m), b))
    case("glb-image-view-past-buffer", "glb/image-view-past-buffer.glb", "error",
         "an image bufferView of 4096 bytes in a 68-byte buffer")
    m = base(None)
    corrupt = corrupt_pngs()["idat-crc"]
    m["buffers"][0]["byteLength"] = 68 + len(corrupt)
    m["bufferViews"].append({"buffer": 0, "byteOffset": 68, "byteLength": len(corrupt)})
    m["images"] = [{"bufferView": 3, "mimeType": "image/png"}]
    m["textures"] = [{"source": 0}]
    m["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    write("glb/corrupt-embedded-png.glb", glb(glb_json(m), b + corrupt))
    case("glb-corrupt-embedded-png", "glb/corrupt-embedded-png.glb", "error",
         "an embedded PNG (bufferView) with a bad IDAT CRC")


def accessor_cases():
    def variant(rel, name, what, edit, raw=None):
        m = base()
        edit(m)
        model_case(rel, name, "error", what, m, raw)

    def set_(path, value):
        def edit(m):
            target = m
            for key in path[:-1]:
                target = target[key]
            target[path[-1]] = value
        return edit

    variant("accessor/count-stride-overflow.gltf", "accessor-count-stride-overflow",
            "POSITION count 2^60+1 with byteStride 16: count x stride wraps to 0 mod 2^64",
            lambda m: (m["bufferViews"][0].update(byteStride=16), m["accessors"][0].update(count=424242)),
            ("424242", "1152921504606846977"))
    variant("accessor/count-huge.gltf", "accessor-count-huge", "POSITION count 10^18",
            set_(["accessors", 0, "count"], 424242), ("424242", "1000000000000000000"))
    variant("accessor/count-2p64.gltf", "accessor-count-2p64", "indices count 2^64 (not even an unsigned 64-bit value)",
            set_(["accessors", 2, "count"], 424242), ("424242", "18446744073709551616"))
    variant("accessor/count-negative.gltf", "accessor-count-negative", "POSITION count -1",
            set_(["accessors", 0, "count"], -1))
    variant("accessor/byte-offset-near-2p64.gltf", "accessor-byte-offset-near-2p64",
            "accessor byteOffset 2^64-4", set_(["accessors", 0, "byteOffset"], 424242),
            ("424242", "18446744073709551612"))
    variant("accessor/view-offset-near-2p64.gltf", "bufferview-byte-offset-near-2p64",
            "bufferView byteOffset 2^64-1 (offset + length wraps to a small number)",
            set_(["bufferViews", 0, "byteOffset"], 424242), ("424242", "18446744073709551615"))
    variant("accessor/view-length-huge.gltf", "bufferview-byte-length-huge", "bufferView byteLength 2^63",
            set_(["bufferViews", 0, "byteLength"], 424242), ("424242", "9223372036854775808"))
    variant("accessor/view-stride-huge.gltf", "bufferview-byte-stride-huge", "bufferView byteStride 2^32+12",
            set_(["bufferViews", 0, "byteStride"], 4294967308))
    variant("accessor/indices-out-of-range.gltf", "indices-out-of-range", "index 3 of a 3-vertex mesh",
            lambda m: m["buffers"][0].update(uri="data:application/octet-stream;base64," + base64.b64encode(
                GEOMETRY[:60] + struct.pack("<3H", 0, 1, 3) + b"\0\0").decode()))
    variant("accessor/indices-u32-max.gltf", "indices-u32-max", "a u32 index 0xFFFFFFFF",
            lambda m: (m["buffers"][0].update(byteLength=72, uri="data:application/octet-stream;base64," +
                                              base64.b64encode(GEOMETRY[:60] + struct.pack("<3I", 0, 1, 0xFFFFFFFF))
                                              .decode()),
                       m["bufferViews"][2].update(byteLength=12), m["accessors"][2].update(componentType=5125)))
    variant("accessor/position-doubles.gltf", "accessor-component-type-5130", "POSITION componentType 5130 (double)",
            set_(["accessors", 0, "componentType"], 5130))
    variant("accessor/component-type-negative.gltf", "accessor-component-type-negative",
            "POSITION componentType -1", set_(["accessors", 0, "componentType"], -1))
    variant("accessor/indices-float.gltf", "accessor-indices-float", "indices with componentType 5126 (float)",
            lambda m: (m["accessors"][2].update(componentType=5126, count=1)))
    variant("accessor/position-u8.gltf", "accessor-position-u8", "POSITION of unnormalized unsigned bytes",
            set_(["accessors", 0, "componentType"], 5121))
    variant("accessor/type-vec7.gltf", "accessor-type-vec7", "POSITION type 'VEC7'",
            set_(["accessors", 0, "type"], "VEC7"))
    variant("accessor/position-scalar.gltf", "accessor-position-scalar", "POSITION of type SCALAR",
            lambda m: m["accessors"][0].update(type="SCALAR", count=9))
    variant("accessor/sparse-index-out-of-range.gltf", "sparse-index-out-of-range",
            "a sparse accessor that replaces element 1000 of 3",
            lambda m: m["accessors"][0].update(sparse={
                "count": 1, "indices": {"bufferView": 2, "componentType": 5123, "byteOffset": 0},
                "values": {"bufferView": 0}}) or m["buffers"][0].update(
                uri="data:application/octet-stream;base64," +
                base64.b64encode(GEOMETRY[:60] + struct.pack("<3H", 1000, 1, 2) + b"\0\0").decode()))
    variant("accessor/sparse-count-huge.gltf", "sparse-count-huge", "sparse count 2^40 over a 3-element accessor",
            lambda m: m["accessors"][0].update(sparse={
                "count": 1099511627776, "indices": {"bufferView": 2, "componentType": 5123},
                "values": {"bufferView": 0}}))
    variant("accessor/buffer-length-huge.gltf", "buffer-byte-length-huge",
            "buffer byteLength 2^62 for 68 bytes of data", set_(["buffers", 0, "byteLength"], 4611686018427387904))
    variant("accessor/buffer-shorter-than-length.gltf", "buffer-data-shorter-than-length",
            "data: URI of 68 bytes for a buffer of byteLength 4096", set_(["buffers", 0, "byteLength"], 4096))
    variant("accessor/missing-position.gltf", "primitive-without-position", "a primitive without POSITION",
            lambda m: m["meshes"][0]["primitives"][0]["attributes"].pop("POSITION"))
    variant("accessor/mode-99.gltf", "primitive-mode-99", "primitive mode 99",
            set_(["meshes", 0, "primitives", 0, "mode"], 99))
    variant("accessor/mesh-index-2p32.gltf", "node-mesh-index-2p32", "node mesh index 2^32 (wraps to 0 as an int)",
            set_(["nodes", 0, "mesh"], 4294967296))
    variant("accessor/material-out-of-range.gltf", "material-index-out-of-range", "primitive material 7 of 1",
            set_(["meshes", 0, "primitives", 0, "material"], 7))
    variant("accessor/texture-source-out-of-range.gltf", "texture-source-out-of-range",
            "a baseColorTexture whose image 5 does not exist",
            lambda m: (m.update(textures=[{"source": 5}]),
                       m["materials"][0]["pbrMetallicRoughness"].update(baseColorTexture={"index": 0})))
    variant("accessor/primitives-object.gltf", "mesh-primitives-object",
            "mesh primitives an object, not an array (rendered zero triangles)",
            lambda m: m["meshes"][0].update(primitives=m["meshes"][0]["primitives"][0]))
    variant("accessor/attribute-index-float.gltf", "attribute-index-float", "POSITION accessor 0.5",
            set_(["meshes", 0, "primitives", 0, "attributes", "POSITION"], 0.5))
    variant("accessor/count-float.gltf", "accessor-count-float", "accessor count 2.5",
            set_(["accessors", 0, "count"], 2.5))
    variant("accessor/buffer-view-index-2p32-plus-1.gltf", "accessor-buffer-view-2p32-plus-1",
            "accessor bufferView 2^32 + 1 (wraps to 1 as an int)", set_(["accessors", 0, "bufferView"], 4294967297))
    variant("accessor/texcoord-huge.gltf", "texture-texcoord-1e300", "baseColorTexture texCoord 1e300",
            lambda m: (m.update(images=[{"uri": "data:image/png;base64," + base64.b64encode(VALID_PNG).decode()}],
                                textures=[{"source": 0}]),
                       m["materials"][0]["pbrMetallicRoughness"].update(
                           baseColorTexture={"index": 0, "texCoord": 424242})),
            ("424242", "1e300"))


def node_cases():
    def nodes(rel, name, what, expect, node_list, roots, raw=None):
        m = base()
        m["nodes"] = node_list + [{"name": "camera", "camera": 0, "translation": [0.0, 0.0, 3.0]}]
        m["scenes"][0]["nodes"] = roots + [len(node_list)]
        model_case(rel, name, expect, what, m, raw)

    nodes("node/cycle-self.gltf", "node-cycle-self", "node 0 is its own child", "error",
          [{"mesh": 0, "children": [0]}], [0])
    nodes("node/cycle-two.gltf", "node-cycle-two", "nodes 0 and 1 are each other's child", "error",
          [{"mesh": 0, "children": [1]}, {"children": [0]}], [0])
    nodes("node/cycle-below-root.gltf", "node-cycle-below-root", "a 3-cycle below a root node", "error",
          [{"children": [1]}, {"mesh": 0, "children": [2]}, {"children": [3]}, {"children": [1]}], [0])
    nodes("node/two-parents.gltf", "node-two-parents", "node 2 is a child of nodes 0 and 1 (glTF forbids)", "error",
          [{"children": [2]}, {"children": [2]}, {"mesh": 0}], [0, 1])
    nodes("node/root-and-child.gltf", "node-root-also-child", "node 1 is a root and the child of root 0", "error",
          [{"children": [1]}, {"mesh": 0}], [0, 1])
    dag = [{"children": [i + 1, i + 1]} for i in range(40)] + [{"mesh": 0}]
    nodes("node/dag-40-levels.gltf", "node-dag-2p40-instances",
          "40 levels, each node listing the next twice: 2^40 instances of one triangle", "error", dag, [0])
    nodes("node/child-out-of-range.gltf", "node-child-out-of-range", "children [99] of 2 nodes", "error",
          [{"mesh": 0, "children": [99]}], [0])
    nodes("node/child-negative.gltf", "node-child-negative", "children [-1]", "error",
          [{"mesh": 0, "children": [-1]}], [0])
    nodes("node/scene-root-out-of-range.gltf", "scene-root-out-of-range", "scene nodes [1000000]", "error",
          [{"mesh": 0}], [1000000])
    nodes("node/matrix-inf.gltf", "node-matrix-inf", "a matrix element 1e999 (inf)", "error",
          [{"mesh": 0, "matrix": [1, 0, 0, 0, 0, 424242, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}], [0], ("424242", "1e999"))
    nodes("node/translation-1e308-twice.gltf", "node-translation-overflow",
          "two nested translations of 1e308: the world position overflows to inf", "error",
          [{"translation": [1e308, 0, 0], "children": [1]}, {"translation": [1e308, 0, 0], "mesh": 0}], [0])
    nodes("node/scale-overflow.gltf", "node-scale-overflow",
          "nested scales 1e200 x 1e200: inf, then inf x 0 = NaN in the composed matrix", "error",
          [{"scale": [1e200, 1e200, 1e200], "children": [1]}, {"scale": [1e200, 1e200, 1e200], "mesh": 0}], [0])
    nodes("node/rotation-zero.gltf", "node-rotation-zero-quaternion",
          "rotation (0, 0, 0, 0): no unit quaternion (glm quietly normalizes it to the identity)", "error", [{"rotation": [0, 0, 0, 0], "mesh": 0}], [0])
    nodes("node/rotation-three.gltf", "node-rotation-three-components", "rotation with 3 components", "error",
          [{"rotation": [0, 0, 1], "mesh": 0}], [0])
    nodes("node/children-object.gltf", "node-children-object", "children {\"0\": 1}, not an array", "error",
          [{"mesh": 0, "children": {"0": 1}}, {}], [0])
    nodes("node/rotation-inf.gltf", "node-rotation-inf", "rotation (1e999, 0, 0, 1)", "error",
          [{"rotation": [424242, 0, 0, 1], "mesh": 0}], [0], ("424242", "1e999"))
    m = base()
    m["nodes"][1]["matrix"] = [0.0] * 16
    gltf("node/camera-matrix-zero.gltf", m)
    case("camera-matrix-singular", "node/camera-matrix-zero.gltf", "error", "the camera node's matrix is all zeros")
    m = base()
    m["nodes"][1]["scale"] = [1.0, 0.0, 1.0]
    gltf("node/camera-scale-y-zero.gltf", m)
    case("camera-scale-singular", "node/camera-scale-y-zero.gltf", "error",
         "the camera node's scale (1, 0, 1) collapses its up axis")
    m = base()
    m["scene"] = 3
    gltf("node/default-scene-out-of-range.gltf", m)
    case("default-scene-out-of-range", "node/default-scene-out-of-range.gltf", "error", "scene 3 of 1")


def camera_cases():
    def camera(rel, name, what, perspective=None, raw=None, cam=None, extras=None):
        m = base()
        if perspective is not None:
            m["cameras"][0]["perspective"].update(perspective)
        if cam is not None:
            m["cameras"][0] = cam
        if extras is not None:
            m["nodes"][1]["extras"] = extras
        model_case(rel, name, "error", what, m, raw)

    camera("camera/yfov-zero.gltf", "camera-yfov-0", "yfov 0", {"yfov": 0.0})
    camera("camera/yfov-negative.gltf", "camera-yfov-negative", "yfov -0.5", {"yfov": -0.5})
    camera("camera/yfov-inf.gltf", "camera-yfov-inf", "yfov 1e999 (inf; JSON has no NaN)", {"yfov": 424242},
           ("424242", "1e999"))
    camera("camera/yfov-4.gltf", "camera-yfov-past-pi", "yfov 4 (more than pi)", {"yfov": 4.0})
    camera("camera/ortho-ymag-zero.gltf", "camera-ortho-ymag-0", "orthographic ymag 0",
           cam={"type": "orthographic", "orthographic": {"xmag": 1.0, "ymag": 0.0, "znear": 0.01, "zfar": 10.0}})
    camera("camera/type-unknown.gltf", "camera-type-unknown", "camera type 'fisheye'",
           cam={"type": "fisheye", "perspective": {"yfov": 0.9, "znear": 0.01}})
    camera("camera/aperture-negative.gltf", "camera-aperture-negative", "thin lens aperture -1",
           extras={"aperture": -1.0, "focusDistance": 2.0})
    camera("camera/focus-inf.gltf", "camera-focus-distance-inf", "thin lens focusDistance 1e999",
           extras={"aperture": 0.1, "focusDistance": 424242}, raw=("424242", "1e999"))
    m = base()
    m["nodes"][1]["camera"] = 7
    gltf("camera/index-out-of-range.gltf", m)
    case("camera-index-out-of-range", "camera/index-out-of-range.gltf", "error", "node camera 7 of 1")


def light_cases():
    def light(rel, name, what, lt, raw=None, node_extra=None):
        model_case(rel, name, "error", what, with_light(lt, node_extra), raw)

    point = {"type": "point", "color": [1.0, 1.0, 1.0], "intensity": 1.0}
    light("light/intensity-negative.gltf", "light-intensity-negative", "point light intensity -1",
          dict(point, intensity=-1.0))
    light("light/intensity-nan.gltf", "light-intensity-nan", "point light intensity NaN (a non-JSON token)",
          dict(point, intensity=424242), ("424242", "NaN"))
    light("light/intensity-1e39.gltf", "light-intensity-1e39", "intensity 1e39: finite as a double, inf as a float",
          dict(point, intensity=1e39))
    light("light/intensity-1e999.gltf", "light-intensity-inf", "intensity 1e999 (inf)", dict(point, intensity=424242),
          ("424242", "1e999"))
    light("light/color-1e39.gltf", "light-color-1e39", "colour (1e39, 1, 1): inf as a float",
          dict(point, color=[1e39, 1.0, 1.0]))
    light("light/color-intensity-product.gltf", "light-color-times-intensity-overflow",
          "colour 1e20 x intensity 1e20: each a finite float, the product inf", dict(point, color=[1e20, 1e20, 1e20],
                                                                                     intensity=1e20))
    light("light/color-negative.gltf", "light-color-negative", "colour (-1, 1, 1)",
          dict(point, color=[-1.0, 1.0, 1.0]))
    light("light/type-unknown.gltf", "light-type-unknown", "light type 'area'", dict(point, type="area"))
    light("light/spot-cone-inverted.gltf", "spot-cone-inverted", "innerConeAngle 0.8 > outerConeAngle 0.2",
          {"type": "spot", "intensity": 1.0, "spot": {"innerConeAngle": 0.8, "outerConeAngle": 0.2}})
    light("light/rect-spot-hfov-180.gltf", "rect-spot-hfov-180", "rectangular spot extras hfov 180",
          {"type": "spot", "intensity": 1.0, "extras": {"hfov": 180.0, "vfov": 30.0}})
    light("light/sphere-radius-1e-40.gltf", "sphere-radius-1e-40",
          "sphere light radius 1e-40: 0 or denormal as a float, radiance I/(pi r^2) overflows",
          dict(point, extras={"radius": 1e-40}))
    light("light/sphere-radius-negative.gltf", "sphere-radius-negative", "sphere light radius -0.1",
          dict(point, extras={"radius": -0.1}))
    light("light/sphere-radius-1e39.gltf", "sphere-radius-1e39", "sphere light radius 1e39 (inf as a float)",
          dict(point, extras={"radius": 1e39}))
    light("light/sphere-radius-string.gltf", "sphere-radius-string", "sphere light radius \"big\"",
          dict(point, extras={"radius": "big"}))
    light("light/index-1e20.gltf", "light-index-1e20", "node light index 1e20 (no int holds it)", point,
          node_extra={"extensions": {"KHR_lights_punctual": {"light": 1e20}}})
    light("light/rect-spot-hfov-string.gltf", "rect-spot-hfov-string",
          "rectangular spot extras hfov \"wide\" (was read as a round spot)",
          {"type": "spot", "intensity": 1.0, "extras": {"hfov": "wide", "vfov": 30.0}})
    light("light/index-out-of-range.gltf", "light-index-out-of-range", "node light index 3 of 1", point,
          node_extra={"extensions": {"KHR_lights_punctual": {"light": 3}}})
    light("light/node-scale-zero.gltf", "light-node-singular", "a spot light on a node of scale 0",
          {"type": "spot", "intensity": 1.0}, node_extra={"scale": [0.0, 0.0, 0.0]})


def material_cases():
    def material(rel, name, what, edit, raw=None):
        m = base()
        edit(m["materials"][0])
        for ext in m["materials"][0].get("extensions", {}):
            if ext not in m["extensionsUsed"]:
                m["extensionsUsed"].append(ext)
        model_case(rel, name, "error", what, m, raw)

    def ext(name, values):
        return lambda mat: mat.setdefault("extensions", {}).update({name: values})

    material("material/ior-negative.gltf", "material-ior-negative", "KHR_materials_ior ior -1",
             ext("KHR_materials_ior", {"ior": -1.0}))
    material("material/ior-inf.gltf", "material-ior-inf", "KHR_materials_ior ior 1e999 (inf)",
             ext("KHR_materials_ior", {"ior": 424242}), ("424242", "1e999"))
    material("material/ior-nan.gltf", "material-ior-nan", "KHR_materials_ior ior NaN (a non-JSON token)",
             ext("KHR_materials_ior", {"ior": 424242}), ("424242", "NaN"))
    material("material/ior-1e39.gltf", "material-ior-1e39", "KHR_materials_ior ior 1e39 (inf as a float)",
             ext("KHR_materials_ior", {"ior": 1e39}))
    material("material/emissive-strength-negative.gltf", "material-emissive-strength-negative",
             "emissiveStrength -5", ext("KHR_materials_emissive_strength", {"emissiveStrength": -5.0}))
    material("material/emissive-strength-1e39.gltf", "material-emissive-strength-1e39",
             "emissiveStrength 1e39 (inf as a float)", ext("KHR_materials_emissive_strength",
                                                           {"emissiveStrength": 1e39}))
    material("material/base-color-1e39.gltf", "material-base-color-1e39", "baseColorFactor (1e39, 0.8, 0.8, 1)",
             lambda mat: mat["pbrMetallicRoughness"].update(baseColorFactor=[1e39, 0.8, 0.8, 1.0]))
    material("material/base-color-short.gltf", "material-base-color-two-components",
             "baseColorFactor with 2 components", lambda mat: mat["pbrMetallicRoughness"].update(
                 baseColorFactor=[0.5, 0.5]))
    material("material/roughness-negative.gltf", "material-roughness-negative", "roughnessFactor -1",
             lambda mat: mat["pbrMetallicRoughness"].update(roughnessFactor=-1.0))
    material("material/transmission-inf.gltf", "material-transmission-inf", "transmissionFactor 1e999",
             ext("KHR_materials_transmission", {"transmissionFactor": 424242}), ("424242", "1e999"))
    material("material/emissive-four-components.gltf", "material-emissive-four-components",
             "emissiveFactor with 4 components", lambda mat: mat.update(emissiveFactor=[1.0, 1.0, 1.0, 1.0]))
    material("material/roughness-string.gltf", "material-roughness-string",
             "roughnessFactor \"0.5\" (the glTF library skips it: roughness 1)",
             lambda mat: mat["pbrMetallicRoughness"].update(roughnessFactor="0.5"))
    material("material/thickness-string.gltf", "material-thickness-string",
             "KHR_materials_volume thicknessFactor \"thick\" (read as thin-walled)",
             ext("KHR_materials_volume", {"thicknessFactor": "thick"}))
    material("material/texture-info-number.gltf", "material-texture-info-number",
             "baseColorTexture 0 instead of {\"index\": 0}",
             lambda mat: mat["pbrMetallicRoughness"].update(baseColorTexture=0))
    material("material/extension-string.gltf", "material-extension-string",
             "KHR_materials_specular \"none\" instead of an object (the glTF library skips it)",
             ext("KHR_materials_specular", "none"))


def extension_cases():
    """Versions, required extensions and the mesh extensions (Draco, instancing)."""
    m = base()
    m["asset"]["version"] = "1.0"
    model_case("ext/gltf-1.gltf", "ext-gltf-1-version", "error", "asset.version 1.0 (glTF 1.0)", m)
    m = base()
    m["extensionsUsed"].append("EXT_meshopt_compression")
    m["extensionsRequired"] = ["EXT_meshopt_compression"]
    m["buffers"].append({"byteLength": 100000, "extensions": {"EXT_meshopt_compression": {"fallback": True}}})
    model_case("ext/meshopt-fallback.gltf", "ext-meshopt-required", "error",
               "EXT_meshopt_compression required, with its data-less fallback buffer", m)

    def draco(rel, name, what, edit):
        m = base()
        m["extensionsUsed"].append("KHR_draco_mesh_compression")
        m["extensionsRequired"] = ["KHR_draco_mesh_compression"]
        prim = m["meshes"][0]["primitives"][0]
        prim["extensions"] = {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}
        edit(m, prim)
        model_case(rel, name, "error", what, m)
    draco("ext/draco-garbage.gltf", "ext-draco-garbage", "a Draco primitive whose bytes are not Draco data",
          lambda m, prim: None)
    draco("ext/draco-view-missing.gltf", "ext-draco-view-missing", "a Draco primitive naming bufferView 9",
          lambda m, prim: prim["extensions"]["KHR_draco_mesh_compression"].update(bufferView=9))
    draco("ext/draco-attributes-array.gltf", "ext-draco-attributes-array", "Draco attributes [0] (not an object)",
          lambda m, prim: prim["extensions"]["KHR_draco_mesh_compression"].update(attributes=[0]))

    def instanced(rel, name, what, attributes):
        m = base()
        m["extensionsUsed"].append("EXT_mesh_gpu_instancing")
        m["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": attributes}}
        model_case(rel, name, "error", what, m)
    instanced("ext/instancing-none.gltf", "ext-instancing-none", "EXT_mesh_gpu_instancing without attributes", {})
    instanced("ext/instancing-vec2.gltf", "ext-instancing-translation-vec2",
              "instance TRANSLATION given the VEC2 texture coordinates", {"TRANSLATION": 1})
    instanced("ext/instancing-index-out.gltf", "ext-instancing-index-out", "instance SCALE accessor 77",
              {"SCALE": 77})


def uri_cases():
    def buffer_uri(rel, name, what, uri, setup="-", names="-"):
        gltf(rel, base(uri))
        case(name, rel, "error", what, setup=setup, names=names)

    # Scenes one directory down, so that "../shared/..." names a real, valid file.
    buffer_uri("uri/buffer-etc-passwd-4-up.gltf", "buffer-uri-etc-passwd-4-up", "buffer uri ../../../../etc/passwd",
               "../../../../etc/passwd")
    buffer_uri("uri/buffer-etc-passwd-16-up.gltf", "buffer-uri-etc-passwd-16-up",
               "buffer uri (../ x 16)etc/passwd: / whatever the depth", "../" * 16 + "etc/passwd")
    buffer_uri("uri/buffer-dev-zero-up.gltf", "buffer-uri-dev-zero-up", "buffer uri (../ x 16)dev/zero, endless",
               "../" * 16 + "dev/zero")
    buffer_uri("uri/buffer-absolute.gltf", "buffer-uri-absolute", "buffer uri /etc/passwd", "/etc/passwd")
    buffer_uri("uri/buffer-absolute-dev-zero.gltf", "buffer-uri-absolute-dev-zero", "buffer uri /dev/zero",
               "/dev/zero")
    buffer_uri("uri/buffer-parent-existing.gltf", "buffer-uri-parent-directory",
               "buffer uri ../shared/triangle.bin: a valid buffer, but outside the scene's directory",
               "../shared/triangle.bin")
    buffer_uri("uri/buffer-dot-dot-inside.gltf", "buffer-uri-up-and-down",
               "buffer uri ../uri/../shared/triangle.bin", "../uri/../shared/triangle.bin")
    buffer_uri("uri/buffer-percent-dot-dot.gltf", "buffer-uri-percent-encoded-parent",
               "buffer uri %2e%2e/shared/triangle.bin", "%2e%2e/shared/triangle.bin")
    buffer_uri("uri/buffer-backslash.gltf", "buffer-uri-backslash-parent", "buffer uri ..\\shared\\triangle.bin",
               "..\\shared\\triangle.bin")
    buffer_uri("uri/buffer-file-scheme.gltf", "buffer-uri-file-scheme", "buffer uri file:///etc/passwd",
               "file:///etc/passwd")
    buffer_uri("uri/buffer-http.gltf", "buffer-uri-http", "buffer uri http://127.0.0.1:9/triangle.bin",
               "http://127.0.0.1:9/triangle.bin")
    buffer_uri("uri/buffer-shell.gltf", "buffer-uri-shell-expansion",
               "buffer uri $(touch pwned)`touch pwned2`~/x.bin: no shell expansion (no file 'pwned' appears)",
               "$(touch pwned)`touch pwned2`~/x.bin")
    buffer_uri("uri/buffer-directory.gltf", "buffer-uri-directory", "buffer uri '.': a directory", ".")
    buffer_uri("uri/buffer-subdirectory.gltf", "buffer-uri-subdirectory", "buffer uri 'sub': a directory", "sub")
    write("uri/sub/.keep", b"")
    buffer_uri("uri/buffer-empty.gltf", "buffer-uri-empty-string", "buffer uri ''", "")
    buffer_uri("uri/buffer-fifo.gltf", "buffer-uri-fifo", "buffer uri naming a FIFO (opening it blocks forever)",
               "fifo.bin", setup="mkfifo:uri/fifo.bin")
    buffer_uri("uri/buffer-in-cwd-only.gltf", "buffer-uri-only-in-cwd",
               "buffer uri cwd-only.bin: missing beside the scene, present in the working directory",
               "cwd-only.bin", setup="cwd:shared/triangle.bin=cwd-only.bin")
    buffer_uri("uri/buffer-data-bad-base64.gltf", "buffer-data-uri-bad-base64", "buffer data: URI with '@' in base64",
               "data:application/octet-stream;base64,@@@@" + DATA_URI.split(",")[1][4:])
    buffer_uri("uri/buffer-data-not-base64.gltf", "buffer-data-uri-not-base64",
               "buffer data: URI without ;base64", "data:application/octet-stream," + "A" * 68)
    buffer_uri("uri/buffer-data-empty.gltf", "buffer-data-uri-empty", "buffer data: URI with no data",
               "data:application/octet-stream;base64,")
    buffer_uri("uri/buffer-data-wrong-mime.gltf", "buffer-data-uri-wrong-mime", "buffer data: URI of type text/html",
               "data:text/html;base64," + DATA_URI.split(",")[1])

    def image_uri(rel, name, what, image, setup="-"):
        gltf(rel, with_texture(image))
        case(name, rel, "error", what, setup=setup)

    image_uri("uri/image-parent.gltf", "image-uri-parent-directory",
              "image uri ../shared/texture.png: a valid PNG outside the scene's directory",
              {"uri": "../shared/texture.png"})
    image_uri("uri/image-etc-passwd.gltf", "image-uri-etc-passwd-up", "image uri (../ x 16)etc/passwd",
              {"uri": "../" * 16 + "etc/passwd"})
    image_uri("uri/image-absolute.gltf", "image-uri-absolute", "image uri /etc/passwd", {"uri": "/etc/passwd"})
    image_uri("uri/image-dev-zero.gltf", "image-uri-absolute-dev-zero", "image uri /dev/zero", {"uri": "/dev/zero"})
    image_uri("uri/image-file-scheme.gltf", "image-uri-file-scheme", "image uri file:///etc/passwd",
              {"uri": "file:///etc/passwd"})
    image_uri("uri/image-https.gltf", "image-uri-https", "image uri https://127.0.0.1:9/t.png",
              {"uri": "https://127.0.0.1:9/t.png"})
    image_uri("uri/image-directory.gltf", "image-uri-directory", "image uri 'sub': a directory", {"uri": "sub"})
    image_uri("uri/image-fifo.gltf", "image-uri-fifo", "image uri naming a FIFO", {"uri": "fifo.png"},
              setup="mkfifo:uri/fifo.png")
    image_uri("uri/image-in-cwd-only.gltf", "image-uri-only-in-cwd",
              "image uri cwd-only.png: missing beside the scene, present in the working directory",
              {"uri": "cwd-only.png"}, setup="cwd:shared/texture.png=cwd-only.png")
    image_uri("uri/image-data-bad-base64.gltf", "image-data-uri-bad-base64", "image data: URI with '!' in base64",
              {"uri": "data:image/png;base64,!!!!" + base64.b64encode(VALID_PNG).decode()[4:]})
    image_uri("uri/image-data-gif.gltf", "image-data-uri-gif", "image data: URI of type image/gif (a PNG inside)",
              {"uri": "data:image/gif;base64," + base64.b64encode(VALID_PNG).decode()})
    image_uri("uri/image-data-corrupt-png.gltf", "image-data-uri-corrupt-png", "image data: URI of a corrupt PNG",
              {"uri": "data:image/png;base64," + base64.b64encode(corrupt_pngs()["idat-crc"]).decode()})
    image_uri("uri/image-data-truncated.gltf", "image-data-uri-truncated", "image data: URI cut inside its base64",
              {"uri": "data:image/png;base64," + base64.b64encode(VALID_PNG).decode()[:30]})


def corrupt_pngs():
    rows = rgb_rows(2, 2)
    good_idat = zlib.compress(rows, 9)
    bad_stream = bytearray(good_idat)
    bad_stream[2] ^= 0xFF  # the first deflate block header: an invalid block type or lengths
    return {
        "ihdr-crc": png(2, 2, rows, ihdr_crc=0xDEADBEEF),
        "idat-crc": png(2, 2, rows, idat_crc=0xDEADBEEF),
        "bad-deflate": png(2, 2, rows, idat=bytes(bad_stream)),
        "truncated": VALID_PNG[: len(VALID_PNG) - 20],
        "header-only": PNG_SIGNATURE,
        "zero-size": png(0, 0, b"", idat=zlib.compress(b"")),
        "bit-depth-3": png(2, 2, rows, bit_depth=3),
        "colour-type-5": png(2, 2, rows, colour_type=5),
        "short-rows": png(64, 64, rgb_rows(64, 2)),
        "huge-header": png(100000, 100000, rgb_rows(1, 1)),
        "width-2p31": png(0x7FFFFFFF, 1, rgb_rows(1, 1)),
        "bad-signature": b"\x89PNX\r\n\x1a\n" + VALID_PNG[8:],
    }


def image_cases():
    for key, data in corrupt_pngs().items():
        write("images/%s.png" % key, data)
        gltf("images/png-%s.gltf" % key, with_texture({"uri": "%s.png" % key}))
    described = {
        "ihdr-crc": "a PNG whose IHDR CRC is wrong",
        "idat-crc": "a PNG whose IDAT CRC is wrong (libpng must not add its own stderr line)",
        "bad-deflate": "a PNG whose IDAT holds a broken deflate stream",
        "truncated": "a valid PNG missing its last 20 bytes",
        "header-only": "the 8-byte PNG signature alone",
        "zero-size": "a 0x0 PNG",
        "bit-depth-3": "a PNG of bit depth 3",
        "colour-type-5": "a PNG of colour type 5",
        "short-rows": "a 64x64 PNG holding 2 rows of pixel data",
        "huge-header": "a PNG claiming 100000x100000 (a few bytes of data)",
        "width-2p31": "a PNG claiming width 2^31-1",
        "bad-signature": "a PNG whose signature is damaged",
    }
    for key in corrupt_pngs():
        case("png-" + key, "images/png-%s.gltf" % key, "error", described[key])
    # 16384 x 16384 1-bit grey: 32 MB of scanlines that deflate to about 33 KB and expand
    # to 2^28 texels, 1 GiB as RGBA8.
    width = height = 16384
    rows = (b"\0" + b"\0" * (width // 8)) * height
    write("images/bomb-16384.png", png(width, height, rows, bit_depth=1, colour_type=0))
    gltf("images/png-bomb.gltf", with_texture({"uri": "bomb-16384.png"}))
    case("png-decompression-bomb", "images/png-bomb.gltf", "error",
         "a 33 KB 1-bit PNG of 16384x16384 that decodes to a 1 GiB RGBA8 texture")
    jpeg = b"\xff\xd8\xff\xe0" + struct.pack(">H", 16) + b"JFIF\0\x01\x01\0\0\x01\0\x01\0\0"
    jpeg += b"\xff\xc0" + struct.pack(">HBHHB", 17, 8, 65500, 65500, 3) + b"\x01\x11\0\x02\x11\0\x03\x11\0"
    write("images/header-only.jpg", jpeg)
    gltf("images/jpeg-header-only.gltf", with_texture({"uri": "header-only.jpg"}))
    case("jpeg-header-only", "images/jpeg-header-only.gltf", "error",
         "a JPEG of SOI, JFIF and a 65500x65500 SOF0, then nothing")
    write("images/text.png", "this is not a PNG\n")
    gltf("images/png-text.gltf", with_texture({"uri": "text.png"}))
    case("png-text-file", "images/png-text.gltf", "error", "a text file named .png")


def environment_cases():
    def env(rel, name, what, env_file=None, data=None, extra=None, names=None):
        if data is not None:
            write("env/" + env_file, data)
        e = {"uri": env_file}
        e.update(extra or {})
        gltf(rel, with_environment(e))
        if names is None:
            names = os.path.basename(rel) + "|" + env_file  # the scene, or the map it names
        case(name, rel, "error", what, names=names)

    env("env-hdr-huge.gltf", "env-hdr-100000x100000", "an HDR environment claiming 100000x100000 (16 bytes of data)",
        "env/huge.hdr", None)
    write("env/huge.hdr", hdr(100000, 100000, pixels=bytes((128, 128, 128, 129)) * 4))
    env("env-hdr-truncated.gltf", "env-hdr-truncated", "an 8x4 HDR holding 5 texels", "env/truncated.hdr", None)
    write("env/truncated.hdr", hdr(8, 4)[:-108])
    env("env-hdr-zero.gltf", "env-hdr-0x0", "an HDR of 0x0 texels", "env/zero.hdr", None)
    write("env/zero.hdr", hdr(0, 0, pixels=b""))
    env("env-hdr-garbage.gltf", "env-hdr-garbage", "#?RADIANCE and then garbage", "env/garbage.hdr", None)
    write("env/garbage.hdr", b"#?RADIANCE\n" + bytes((i * 91 + 7) % 256 for i in range(300)))
    env("env-hdr-negative.gltf", "env-hdr-negative-size", "an HDR header '-Y -5 +X 8'", "env/negative.hdr", None)
    write("env/negative.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y -5 +X 8\n" + b"\x80\x80\x80\x81" * 8)
    write("env/huge.exr", exr(100000, 100000, offsets=4))
    env("env-exr-huge.gltf", "env-exr-100000x100000", "an EXR whose dataWindow is 100000x100000 (4 offsets)",
        "env/huge.exr")
    write("env/truncated.exr", exr(8, 4)[:-150])
    env("env-exr-truncated.gltf", "env-exr-truncated", "a valid 8x4 EXR missing its last 150 bytes",
        "env/truncated.exr")
    write("env/window-overflow.exr", exr(1, 1, x_min=-0x80000000, x_max=0x7FFFFFFF, y_min=0, y_max=0, offsets=1))
    env("env-exr-window-overflow.gltf", "env-exr-window-overflow",
        "an EXR dataWindow from x -2^31 to 2^31-1: its width overflows an int", "env/window-overflow.exr")
    # Found by tools/fuzz.sh images (the finding's bytes): OpenImageIO sized its read
    # buffer for 256 rows, so one row 8.6 million pixels wide asked for 26 GB.
    write("env/wide.exr", base64.b64decode(
        "di8xAQIAAABjaGFubmVscwBjaGxpc3QANwAAAEIAAgAAAAAAAAABAAAAAQAAAEcAAgAAAAAAAAABAAAAAQAAAFIAAgAAAAAA"
        "AAABAAAAAQAAAABjb21wLXJlc3Npb24AY29tcHJlc3Npb24AAQAAAABkYXRhV2luZG93AGJveDJpABALAAAAAAAAAAAAAAAA"
        "hAAAAAAAAAcAAAAAAAAAABQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQU"
        "FBQUFBQUAAAAPwAAgBUAAIA/AACAPwAAgD8AAIA/AACAPwAAgD8AAIBNTU1NAGAAAAAAAIA+AACBPgAAgD4AAIA+AACAPgAA"
        "gD4AAIA+AACAPgAAAD8AAAA/AAAAPwAAAD8AAAA/AAAAAAA/AAAAPwAAgD8AAIA/AACAPwAAgD8AAIA/AACAPwAAgD8AAIA/"))
    env("env-exr-wide.gltf", "env-exr-one-row-8m-wide",
        "a 1-row EXR 8,650,753 pixels wide (OpenImageIO's read buffer for 256 rows: 26 GB)", "env/wide.exr")
    write("env/window-inverted.exr", exr(8, 4, x_min=7, x_max=0, offsets=4))
    env("env-exr-window-inverted.gltf", "env-exr-window-inverted", "an EXR dataWindow with xMax < xMin",
        "env/window-inverted.exr")
    write("env/header-only.exr", exr(8, 4)[:8])
    env("env-exr-header-only.gltf", "env-exr-magic-only", "the 8 bytes of an EXR's magic and version",
        "env/header-only.exr")
    # Found by tools/fuzz.sh partial: OpenImageIO 2.4 aborts on a pixel type other than
    # uint, half and float, and OpenEXR 3.1 allocates an attribute's claimed size.
    write("env/pixel-type-3.exr", exr(8, 4, pixel_type=3))
    env("env-exr-pixel-type-3.gltf", "env-exr-pixel-type-3", "an EXR whose channels have pixel type 3",
        "env/pixel-type-3.exr")
    write("env/attribute-2gb.exr", exr(8, 4, extra=b"note\0string\0" + struct.pack("<i", 0x7FFF0000) + b"x"))
    env("env-exr-attribute-2gb.gltf", "env-exr-attribute-2gb",
        "an EXR of 778 bytes with a string attribute that claims 2 GB", "env/attribute-2gb.exr")
    env("uri/env-parent.gltf", "env-uri-parent-directory",
        "environment uri ../env/valid.hdr: a valid map outside the scene's directory", "../env/valid.hdr")
    env("env-uri-absolute.gltf", "env-uri-absolute", "environment uri /etc/passwd", "/etc/passwd")
    env("env-uri-dev-zero.gltf", "env-uri-absolute-dev-zero", "environment uri /dev/zero", "/dev/zero")
    env("env-uri-directory.gltf", "env-uri-directory", "environment uri 'env': a directory", "env",
        names="env-uri-directory.gltf|files/env:")
    gltf("env-uri-fifo.gltf", with_environment({"uri": "env/fifo.hdr"}))
    case("env-uri-fifo", "env-uri-fifo.gltf", "error", "environment uri naming a FIFO", setup="mkfifo:env/fifo.hdr",
         names="env-uri-fifo.gltf|env/fifo.hdr")
    gltf("env-uri-in-cwd-only.gltf", with_environment({"uri": "cwd-only.hdr"}))
    case("env-uri-only-in-cwd", "env-uri-in-cwd-only.gltf", "error",
         "environment uri cwd-only.hdr: missing beside the scene, present in the working directory",
         setup="cwd:env/valid.hdr=cwd-only.hdr", names="env-uri-in-cwd-only.gltf|cwd-only.hdr")
    env("env-uri-file-scheme.gltf", "env-uri-file-scheme", "environment uri file:///etc/passwd",
        "file:///etc/passwd")
    env("env-strength-negative.gltf", "env-strength-negative", "environment strength -1", "env/valid.hdr",
        extra={"strength": -1.0}, names="-")
    env("env-strength-1e39.gltf", "env-strength-1e39", "environment strength 1e39 (inf as a float)", "env/valid.hdr",
        extra={"strength": 1e39}, names="-")
    env("env-strength-string.gltf", "env-strength-string", "environment strength \"bright\"", "env/valid.hdr",
        extra={"strength": "bright"}, names="-")
    gltf("env-uri-number.gltf", with_environment({"uri": 7}))
    case("env-uri-not-string", "env-uri-number.gltf", "error", "environment uri 7 (a number)")


def cli_cases():
    """Bad values of the render command's flags, on the valid scene."""
    global CLI_CASES
    before = len(CASES)

    def cli(name, args, what, expect="error", names="-", setup="-", file="valid.gltf"):
        if names == "-" and expect == "error":
            names = args.split()[0]
        case("cli-" + name, file, expect, what, args=args, setup=setup, names=names)

    cli("width-0", "--width 0", "--width 0")
    cli("width-negative", "--width -16", "--width -16")
    cli("width-2p32", "--width 4294967312", "--width 2^32+16 (16 after a 32-bit wrap)")
    cli("width-overflow", "--width 99999999999999999999999", "--width beyond any integer")
    cli("width-past-limit", "--width 65536", "--width 65536 (past the 32768 limit)")
    cli("height-0", "--height 0", "--height 0")
    cli("height-negative", "--height -1", "--height -1")
    cli("height-float", "--height 16.5", "--height 16.5")
    cli("spp-0", "--spp 0", "--spp 0")
    cli("spp-negative", "--spp -1", "--spp -1")
    cli("spp-2p32", "--spp 4294967297", "--spp 2^32+1 (1 after a 32-bit wrap)")
    cli("spp-overflow", "--spp 1e30", "--spp 1e30")
    cli("max-bounces-negative", "--max-bounces -1", "--max-bounces -1")
    cli("env-strength-negative", "--env-strength -1", "--env-strength -1")
    cli("env-strength-nan", "--env-strength nan", "--env-strength nan")
    cli("env-strength-inf", "--env-strength inf", "--env-strength inf")
    cli("env-rotation-nan", "--env-rotation nan", "--env-rotation nan")
    cli("env-rotation-inf", "--env-rotation inf", "--env-rotation inf")
    cli("exposure-nan", "--exposure nan", "--exposure nan")
    cli("exposure-huge", "--exposure 1e6", "--exposure 1e6 (2^1e6 overflows)")
    cli("tone-unknown", "--tone aces", "--tone aces (clip or filmic)")
    cli("background-inf", "--background inf,0,0", "--background inf,0,0")
    cli("background-nan", "--background 0,nan,0", "--background 0,nan,0")
    cli("background-negative", "--background 0,0,-1", "--background 0,0,-1")
    cli("background-1e39", "--background 1e39,0,0", "--background 1e39,0,0 (inf as a float)")
    cli("fov-zero", "--fov 0", "--fov 0")
    cli("fov-nan", "--fov nan", "--fov nan")
    cli("fov-180", "--fov 180", "--fov 180")
    cli("aperture-negative", "--aperture -1 --focus-distance 2", "--aperture -1")
    cli("aperture-nan", "--aperture nan --focus-distance 2", "--aperture nan")
    cli("focus-distance-inf", "--aperture 0.1 --focus-distance inf", "--focus-distance inf",
        names="--focus-distance")
    cli("look-from-nan", "--look-from nan,0,3 --look-at 0,0,0", "--look-from nan,0,3")
    cli("camera-negative", "--camera -2", "--camera -2")
    cli("camera-overflow", "--camera 99999999999", "--camera 99999999999")
    cli("time-nan", "--time nan", "--time nan")
    cli("device-99", "--device 99", "--device 99 (no such device)")
    cli("env-missing", "--env {CWD}/no-such.hdr", "--env naming a missing file", names="no-such.hdr")
    cli("env-directory", "--env {FILES}/env", "--env naming a directory", names="env")
    cli("env-dev-zero", "--env /dev/zero", "--env /dev/zero (an endless character device)", names="/dev/zero")
    cli("env-fifo", "--env {FILES}/env/cli-fifo.hdr", "--env naming a FIFO", names="cli-fifo.hdr",
        setup="mkfifo:env/cli-fifo.hdr")
    cli("env-truncated", "--env {FILES}/env/truncated.exr", "--env naming a truncated EXR", names="truncated.exr")
    cli("env-huge", "--env {FILES}/env/huge.hdr", "--env naming an HDR claiming 100000x100000", names="huge.hdr")
    cli("output-equals-env", "--env {FILES}/env/valid.exr -o {FILES}/env/valid.exr",
        "the output is the --env input (it must not be replaced)", names="valid.exr")
    write("cli/scene-named.exr", dump(base()))
    cli("output-equals-scene", "-o {SCENE}", "a glTF named scene-named.exr rendered onto itself",
        names="scene-named.exr", file="cli/scene-named.exr")
    cli("output-is-scene-gltf", "-o {SCENE}", "-o naming the .gltf input", names="valid.gltf")
    cli("output-missing-dir", "-o {CWD}/missing/out.png", "an output in a missing directory",
        names="missing/out.png")
    cli("output-read-only-dir", "-o {RO}/out.png", "an output in a read-only directory", names="out.png")
    cli("output-is-directory", "-o {CWD}/dir.png", "an output naming an existing directory", names="dir.png",
        setup="mkdir:dir.png")
    cli("output-no-extension", "-o {CWD}/out", "an output without an extension", names="out")
    cli("ray-log-missing-dir", "--ray-log {CWD}/missing/rays.ply", "--ray-log in a missing directory",
        names="rays.ply")
    cli("existing-output-kept", "--spp 0", "an existing output stays byte-identical after an error",
        setup="existing-output", names="--spp")
    gltf("cli/missing-buffer.gltf", base("no-such.bin"))
    cli("existing-output-kept-bad-scene", "-", "an existing output stays byte-identical after a scene error",
        setup="existing-output", names="no-such.bin", file="cli/missing-buffer.gltf")
    cli("scene-missing", "-", "a scene path that does not exist", names="no-such-scene.gltf",
        file="cli/no-such-scene.gltf")
    cli("scene-directory", "-", "a scene path naming a directory (named .gltf)", names="dir.gltf",
        file="cli/dir.gltf")
    write("cli/dir.gltf/.keep", b"")
    cli("scene-fifo", "-", "a scene path naming a FIFO", names="fifo.gltf", file="cli/fifo.gltf",
        setup="mkfifo:cli/fifo.gltf")
    cli("scene-dev-zero", "-", "the scene /dev/zero", names="/dev/zero", file="/dev/zero")
    # Valid flag values around the bad ones still render.
    cli("valid-exposure-filmic", "--exposure -3.5 --tone filmic", "--exposure -3.5 --tone filmic are valid",
        expect="renders")
    cli("valid-env-rotation", "--env {FILES}/env/valid.hdr --env-rotation -720 --env-strength 0",
        "--env-rotation -720 and --env-strength 0 are valid", expect="renders")
    cli("valid-two-outputs", "-o {CWD}/a.png -o {CWD}/b.exr", "two outputs, both written", expect="renders")
    CLI_CASES = len(CASES) - before


def fnv1a64(data):
    h = 0xcbf29ce484222325
    for b in data:
        h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h


def checkpoint(key, pixels=16, version=2, cut=None):
    """A checkpoint as render/checkpoint.cpp writes it (version 2), of a render of
    `pixels` pixels stopped before its first pass, with its checksum."""
    def array(item_size, count, fill=b""):
        return struct.pack("<Q", count) + (fill or b"\0" * item_size * count)
    data = b"PATHCLCP" + struct.pack("<I", version) + array(1, len(key), key)
    data += struct.pack("<IIId", 0, 0, 0, 0.0)
    for _ in range(4):
        data += array(24, 3 * pixels)  # the exact sums (ExactSum, 24 bytes)
    data += array(8, pixels) + array(4, pixels)  # samples, pixel_batches
    data += struct.pack("<QIQ", 0, 0, 1)  # bad samples, batches, one device
    data += array(64, pixels) + array(4, pixels) + array(4, 0)  # its film, bad counts; no mask
    data += struct.pack("<Q", fnv1a64(data))
    return data if cut is None else data[:cut]


def args_file(rel, args):
    """An argument list for tools/fuzz.sh cli: the arguments separated by NUL bytes."""
    write(rel, b"\0".join(a.encode("utf-8") for a in args))


def service_cases():
    """What a render service meets when it runs pathcl on files it did not write:
    checkpoints (--resume), partial renders (merge), special files and other names for
    one file as outputs, and small inputs that ask for unbounded work."""
    key = b"scene 0; size 16x16; seed 0; sampler sobol"
    write("checkpoint/other-render.bin", checkpoint(key))
    case("checkpoint-other-render", "valid.gltf", "error", "--resume of a well-formed checkpoint of another render",
         args="--resume {FILES}/checkpoint/other-render.bin", names="other-render.bin")
    write("checkpoint/line-break-key.bin", checkpoint(b"\n" * 10000))
    case("checkpoint-line-break-key", "valid.gltf", "error",
         "--resume of a checkpoint whose key is 10,000 line breaks (the error stays one short line)",
         args="--resume {FILES}/checkpoint/line-break-key.bin", names="line-break-key.bin")
    write("checkpoint/truncated.bin", checkpoint(key, cut=2000))
    case("checkpoint-truncated", "valid.gltf", "error", "--resume of a checkpoint cut short",
         args="--resume {FILES}/checkpoint/truncated.bin", names="truncated.bin")
    write("checkpoint/version-9.bin", checkpoint(key, version=9))
    case("checkpoint-version-9", "valid.gltf", "error", "--resume of a checkpoint of format version 9",
         args="--resume {FILES}/checkpoint/version-9.bin", names="version-9.bin")
    write("checkpoint/not-a-checkpoint.bin", "not a checkpoint\n")
    case("checkpoint-not-one", "valid.gltf", "error", "--resume of a text file",
         args="--resume {FILES}/checkpoint/not-a-checkpoint.bin", names="not-a-checkpoint.bin")
    case("checkpoint-sparse-3g", "valid.gltf", "error",
         "--resume of a 3 GB sparse file for a 16x16 render (refused from its size, unread)",
         args="--resume {FILES}/checkpoint/huge.bin", setup="sparse:checkpoint/huge.bin:3G", names="huge.bin")
    case("checkpoint-fifo", "valid.gltf", "error", "--resume naming a FIFO",
         args="--resume {FILES}/checkpoint/fifo.bin", setup="mkfifo:checkpoint/fifo.bin", names="fifo.bin")
    case("checkpoint-dev-zero", "valid.gltf", "error", "--resume /dev/zero",
         args="--resume /dev/zero", names="/dev/zero")

    # Partial renders, made by the runner (partial:REL:FIRST:COUNT renders samples
    # FIRST..FIRST+COUNT-1 of the 4x4, 32-spp valid scene in batches of 16), some edited
    # in place (replace:REL|OLD|NEW, bytes of the same length in the EXR's header).
    two = "partial:partial/a.exr:0:16,partial:partial/b.exr:16:16"
    merge = "merge {FILES}/partial/a.exr {FILES}/partial/b.exr -o {CWD}/m.exr"
    case("merge-valid", "-", "renders", "merge of the two halves of a render", args=merge, setup=two)
    case("merge-overlap", "-", "error", "merge of a partial render with itself (its samples would count twice)",
         args="merge {FILES}/partial/a.exr {FILES}/partial/a.exr -o {CWD}/m.exr", setup=two, names="a.exr")
    case("merge-range-not-whole-batches", "-", "error", "pathcl:sample_ranges 16:16 edited to 16:08",
         args=merge, setup=two + ",replace:partial/b.exr|16:16|16:08", names="b.exr")
    case("merge-total-against-key", "-", "error",
         "the render key's spp edited (32 to 64): pathcl:spp_total no longer agrees",
         args=merge, setup=two + ",replace:partial/b.exr|; spp 32;|; spp 64;", names="b.exr")
    case("merge-batch-size-zero", "-", "error", "the render key's batch size edited to 00",
         args=merge, setup=two + ",replace:partial/b.exr|batch spp 16|batch spp 00", names="b.exr")
    case("merge-film-batches-edited", "-", "error", "pathcl:film_batches edited from 1 to 7",
         args=merge, setup=two + ",replace:partial/b.exr|film_batches\\x00string\\x00\\x01\\x00\\x00\\x001|"
                                 "film_batches\\x00string\\x00\\x01\\x00\\x00\\x007", names="b.exr")
    case("merge-film-pixel-type-3", "-", "error", "a film channel's pixel type edited from uint to 3",
         args=merge, setup=two + ",replace:partial/b.exr|batch_mean_sq.B.0\\x00\\x00|batch_mean_sq.B.0\\x00\\x03",
         names="b.exr")
    case("merge-string-attribute-2gb", "-", "error", "pathcl:film_batches's byte count edited to 2 GB",
         args=merge, setup=two + ",replace:partial/b.exr|film_batches\\x00string\\x00\\x01\\x00\\x00\\x00|"
                                 "film_batches\\x00string\\x00\\x01\\x00\\x00\\x7f", names="b.exr")
    # (The image part's: its last channel, variance.R, is float; the film part's are uint.)
    last = "R\\x00\\x02\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x01\\x00\\x00\\x00\\x01\\x00\\x00\\x00"
    count = last + "\\x00chunkCount\\x00int\\x00\\x04\\x00\\x00\\x00"
    case("merge-chunk-count-2-28", "-", "error", "the image part's chunkCount edited from 1 to 2^28",
         args=merge, setup=two + ",replace:partial/b.exr|" + count + "\\x01\\x00\\x00\\x00|" + count + "\\x00\\x00\\x00\\x10",
         names="b.exr")
    # Found by tools/fuzz.sh partial (the findings' bytes): OpenImageIO 2.4 aborted the
    # process on the first two, OpenEXR 3.1 allocated and filled 1.9 GB for the third.
    write("findings/abort-unknown-pixel-type.exr", base64.b64decode(
        "di8xAQIQAABjYXBEYXRlAHN0cmluZwATAAAAMjAyNjoxMToyOCAyMDoxODo1MmNoYW5uZWxzAGNobGlzdACIAAAAQgACAAAAAAAA"
        "AAEAAAABAAAARwACAAAAAAAAAAEAAAABAAAAUgACAAAAAAAAAAEAAAABAAAAdmFyaWFuY2UuQgACAAAAAAAAAAEAAAABAAAAdmFy"
        "aWFuY2UuRwACAAAAAAAAAAEAAAABAAAAdmFyaWFuY2UuUgACAAAAAAAAAAEAAAABAAAAAGNodW5rQ291bnQAaW50AAQAAAABAAAA"
        "Y29tcHJlc3Npb24AY29tcHJlc3Npb24AAQAAAANkYXRhV2luZG93AGJveDJpABAAAAAAAAAAAAAAAAMAAAADAAAAZGlzcGxheVdp"
        "bmRvdwBib3gyaQAQAAAAAAAAAAAAAAADAAAAAwAAAGxpbmVPcmRlcgBsaW5lT3JkZXIAAQAAAABuYW1lAHN0cmluZwAFAAAAaW1h"
        "Z2VwYXRoY2w6YmF0Y2hfc3BwAHN0cmluZwACAAAAMTZwYXRoY2w6YmF0Y2hlcwBzdHJpbmcAAQAAADFwYXRoY2w6ZmlsbV9iYWRf"
        "cyBtcGxlcwBzdHJpbmcAAQAAADBwYXRoY2w6ZmlsbV9iYXRjaGVzAHN0cmluZwABAAAAMnBhdGhjbDpyZWxtc2VfZXN0aW1hdGUA"
        "c3RyaW5nAAkAAAAwLjA3NjkwODJwYXRoY2w6cmVsbXNlX2VzdGltYXRlX21ldGhvZABzdHJpbmcAIQAAAHBlci1zYW0scGxlIHZh"
        "cmlhbmNlICh1cHBlciBib3VuZClwYXRoY2w6cmVuZGVyX2tleQBzdHJpbmcAmwAAAHNjZW5lIGU5YmNjYTkxMDdjNmMwMTg7IHNp"
        "emUgNHg0OyBzZWVkIDA7IHNhbXBsZXIgc29ib2w7IHN0cmF0ZWd5IG1pczsgYm91bmNlcyA4OyBzdHJhdGlmaWVkIGJvdW5jZXMg"
        "MTsgYmF0Y2ggc3BwIDE2OyBzcHAgNDA7IG9wdGlvbnMgMDAwMDsgc2FtcGxlIGxheW91dCAycGF0aGNsOnNhbXBsZV9yYW5nZXMA"
        "c3RyaW5nAAUAAAAxNjoxNnBhdGhjbDpzYW1wbGVyAHN0cmluZwAFAAAAc29ib2xwYXRoY2w6c2VlZABzdHJpbmcAAQAAADBwYXRo"
        "Y2w6c3BwAGludAAEAAAAEAAAAHBhdGhjbDpzcHBfdG90YWwAc3RyaW5nAAIAAAA0MHBhdGhjbDpzdG9wAHN0cmluZwADAAAAc3Bw"
        "cGl4ZWxBc3BlY3RSYXRpbwBmbG9hdAAEAAAAAACAP3NjcmVlbldpbmRvd0NlbnRlcgB2MmYACAAAAAAAAAAAAAAAc2NyZWVuV2lu"
        "ZG93V2lkdGgAZmxvYXQABAAAAAAAgD90eXBlAHN0cmluZwANAAAAc2NhbmxpbmVpbU1NTU1jYXBEYXRlAHNJSUlJdHJpbmcAEwAA"
        "ADIwMjY6MTE6MjggMjA6MTg6NTJjaGFubmVscwBjaGxpc3QApwgAAGJhdGNoX21lYW5fc3EuQi4wAAAAAAAAAAAAAQAAAAEAAABi"
        "YXRjaF9tZWFuX3NxLkIuMQAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbXYvMQECEAAAY2FwRGF0ZQBzdHJpbmcAEwAAADIwMjY6MTE6"
        "MjggMjA6MTg6NTJjaGFubmVscwBjaGxpc3QAiAAAAEIAAgAAAAAAAAABAAAAAQAAAEcAAgAAAAAAAAABAAAAAQAAAFIAAgAAAAAA"
        "AAABAAAAAQAAAHZhcmlhbmNlLkIAAgAAAAAAAAABAAAAAQAAAHZhcmlhbmNlLkcAAgAAAAAAAAABAAAAAQAAAHZhcmlhbmNlLlIA"
        "AgAAAAAAAAABAAAAAQAAAABlYW5fc3EuQi4yAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkIuMwAAAAAAAAAAAAEAAAAB"
        "AAAAYmF0Y2hfbWVhbl9zcS5CLjQAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuQi41AAAAAAAAAAAAAQAAAAEAAABiYXRj"
        "aF9tZWFuX3NxLkcuMAAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5HLjEAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5f"
        "c3EuRy4yAAAAAAAAAAAAAQAAAAEAAABiYXRjaDUAAAAAAAAAAAABAAAAAQAAAABjaHVua0NvdW50AGludAAEAAAAAQAAAGNvbXBy"
        "ZXNzaW9uAGNvbXByZXNzaW9uAAEAAAADZGF0YVdpbmRvdwBib3gyaQAQAAAAAAAAAAAAAAADAAAAAwAAAGRpc3BsYXlXaW5kb3cA"
        "Ym94MmkAEAAAAAAAAAAAAAAAAwAAAAMAAABsaW5lT3JkZXIAbGluZU9yZGVyAAEAAAAAbmFtZQBzdHJpbmcABAAAAGZpbG1waXhl"
        "bEFzcGVjdFJhdGlvAGZsb2F0AAQAAAAAAIA/c2NyZWVuV2luZG93Q2VudGVyAHYyZgAIAAAAAAAAAAAAAABzY3JlZW5XaW5kb3dX"
        "aWR0aABmbG9hdAAEAAAAAACAP3R5cGUAc3RyaW5nAA0AAABzY2FubGluZWltYWdlAABuDgAAAAAAAOEOAAAAAAAAAAAAAAAAAABn"
        "AAAAeF5jaGhgYGgAA2LphAUJC7DQz4DULyx0wwdjaHVua0NvdW50AGludAAEAAAAAQAAAGNvbXByZXNzaW9uAGNvbXByZXNzaW9u"
        "AAEAAAADZGF0YVdpbmRvdwBib3gyaQAQAAAAAAAAAAAAAAADAAAAAwAAAGRpc3BsYXlXaW5kb3cAYm94MmkAEAAAAAAAAAAAAAAA"
        "AwAAAAMAAABsaW5lT3JkZXIAbGluZU9yZGVyAAEAAAAAbmFtZQBzdHJpbmcABQAAAGltYWdlcGF0aGNsOmJhdGNoX3NwcABzdHJp"
        "bmcAAgAAADE2cGF0aGNsOmJhdGNoZXMAc3RyaW5nAAEAAAAxcGF0aGNsOmZpbG1fYmFkX3NhbXBsZXMAc3RyaW5nAAEAAAAwcGF0"
        "aGNsOmZpbG1fYmF0Y2hlcwBzdHJpbmcAAQAAADFwYXRoY2w6cmVsbXNlX2VzdGltYXRlAHN0cmluZwAJAAAAMC4wNzY5MDgycGF0"
        "aGNsOnJlbG1zZV9lc3RpbWF0ZV9tZXRob2QAc3RyaW5nACEAAABwZXItc2FtcGxlIHZhcmlhbmNlICh1cHBlciBib3VuZClwYXRo"
        "Y2w6cmVuZGVyX2tleQBzdHJpbmcAmwAAAHNjZW5lIGU5YmNjYTkxMDdjNmMwMTg7IHNpemUgNHg0OyBzZWVkIDA7IHNhbXBsZXIg"
        "c29ib2w7IHN0cmF0ZWd5IG1pczsgYm91bmNlcyA4OyBzdHJhdGlmaWVkIGJvdW5jZXMgMTsgYmF0Y2ggc3BwIDE2OyBzcHAgNDA7"
        "IG9wdGlvbnMgMDAwMDsgc2FtcGxlIGxheW91dCAycGF0aGNsOnNhbXBsZV9yYW5nZXMAc3RyaW5nAAUAAAAxNjoxNnBhdGhjbDpz"
        "YW1wbGVyAHN0cmluZwAFAAAAc29ib2xwYXRoY2w6c2VlZABzdHJpbmcAAQAAADBwYXRoY2w6c3BwAGludAAEAAAAEAAAAHBhdGhj"
        "bDpzcHBfdG90YWwAc3RyaW5nAAIAAAA0MHBhdGhjbDpzdG9wAHN0cmluZwADAAAAc3BwcGl4ZWxBc3BlY3RSYXRpbwBmbG9hdAAE"
        "AAAAAACAP3NjcmVlbldpbmRvd0NlbnRlcgB2MmYACAAAAAAAAAAAAAAAc2NyZWVuV2luZG93V2lkdGgAZmxvYXQABAAAAAAAgD90"
        "eXBlAHN0cmluZwANAAAAc2NhbmxpbmVpbWFnZQBjYXBEYXRlAHN0cmluZwATAAAAMjAyNjoxMToyOCAyMDoxODo1MmNoYW5uZWxz"
        "AGNobGlzdACnCAAAYmF0Y2hfbWVhbl9zcS5CLjAAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuQi4xAAAAAAAAAAAAAQAA"
        "AAEAAABiYXRjaF9tZWFuX3NxLkIuMgAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5CLjMAAAAAAAAAAAABAAAAAQAAAGJh"
        "dGNoX21lYW5fc3EuQi40AAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkIuNQAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVh"
        "bl9zcS5HLjAAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuRy4xAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcu"
        "MgAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5HLjMAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuRy40AAAAAAAA"
        "AAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcuNQAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5SLjAAAAAAAAAAAAABAAAA"
        "AQAAAGJhdGNoX21lYW5fc3EuUi4xAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLlIuMgAAAAAAAAAAAAEAgQcK2GiG9/WT"
        "MGkGBocDDgew0UAAVIFONzTsdQbpJp7e57TPCQv9LGJFBDa6Yb/jfkds9F7D82ATUem9ziDz9jlhpQ3OO6PRAECQs74BAAAAAAAA"
        "ALEAAAB4Xu3VsQ2DMBCF4YzACAwAAAEAAABiYXRjaF9tZWFuX3NxLlIuMwAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5S"
        "LjQAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuUi41AAAAAAAAAAAAAQAAAAEAAABiYXSTngUoyAZOOlAUx2NoXw=="))
    case("merge-found-abort-unknown-pixel-type", "-", "error",
         "a partial render whose film channel has pixel type 1885430528 (OpenImageIO aborted)",
         args="merge {FILES}/findings/abort-unknown-pixel-type.exr -o {CWD}/m.exr", names="abort-unknown-pixel-type.exr")
    write("findings/abort-channel-list-overrun.exr", base64.b64decode(
        "di8xAQIQAABjYXBEYXRlAHN0cmluZwATAAAAMjAyNjoxMToyOCAyMDoxODo1MmNoYW5uZWxzAGNobGlzdACIAAAAQgACAAAAAAAA"
        "AAEAAAABAAAARwACAAAAAAAAAAEAAAABAAAAUgACAAAAAAAAAAEAAAABAAAAdmFyaWFuY2UuQgACAAAAAAAAAAEAAAABAAAAdmFy"
        "aWFuY2UuRwACAAAAAAAAAAEAAAABAAAAdmFyaWFuY2UuUgACAAAAAAAAAAEAAAABAAAAAGNodW5rQ291bnQAaW50AAQAAAABAAAA"
        "Y29tcHJlc3Npb24AY29tcHJlc3Npb24AAQAAAANkYXRhV2luZG93AGJveDJpABAAAAAAAAAAAAAAAAMAAAADAAAAZGlzcGxheVdp"
        "bmRvdwBib3gyaQAQAAAAAAAAAAAAAAADAAAAAwAAAGxpbmVPcmRlcgBsaW5lT3JkZXIAAQAAAABuYW1lAHN0cmluZwAFAAAAaW1h"
        "Z2VwYXRoY2w6YmF0Y2hfc3BwAHN0cmluZwACAAAAMTZwYXRoY2w6YmF0Y2hlcwBzdHJpbmcAAQAAADFwYXRoY2w6ZmlsbV9iYWRf"
        "cyBtcGxlcwBzdHJpbmcAAQAAADBwYXRoY2w6ZmlsbV9iYXRjaGVzAHN0cmluZwABAAAAMnBhdGhjbDpyZWxtc2VfZXN0aW1hdGUA"
        "c3RyaW5nAAkAAAAwLjA3NjkwODJwYXRoY2w6cmVsbXNlX2VzdGltYXRlX21ldGhvZABzdHJpbmcAIQAAAHBlci1zYW1wbGUgdmFy"
        "aWFuY2UgKHVwcGVyIGJvdW5kKXBhdGhjbDpyZW5kZXJfa2V5AHN0cmluZwCbAAAAc2NlbmUgZTliY2NhOTEwN2M2YzAxODsgc2l6"
        "ZSA0eDQ7IHNlZWQgMDsgc2FtcGxlciBzb2JvbDsgc3RyYXRlZ3kgbWlzOyBib3VuY2VzIDg7IHN0cmF0aWZpZWQgYm91bmNlcyAx"
        "OyBiYXRjaCBzcHAgMTY7IHNwcCA0MDsgb3B0aW9ucyAwMDAwOyBzYW1wbGUgbGF5b3V0IDJwYXRoY2w6c2FtcGxlX3JhbmdlcwBz"
        "dHJpbmcABQAAADE2OjE2cGF0aGNsOnNhbXBsZXIAc3RyaW5nAAUAAABzb2JvbHBhdGhjbDpzZWVkAHN0cmluZwABAAAAMHBhdGhj"
        "bDpzcHAAaW50AAQAAAAQAAAAcGF0aGNsOnNwcF90b3RhbABzdHJpbmcAAgAAADQwcGF0aGNsOnN0b3AAc3RyaW5nAAMAAABzcHBw"
        "aXhlbEFzcGVjdFJhdGlvAGZsb2F0AAQAAAAAAIA/c2NyZWVuV2luZG93Q2VudGVyAHYyZgAIAAAAAAAAAAAAAABzY3JlZW5XaW5k"
        "b3dXaWR0aABmbG9hdAAEAAAAAACAP3R5cGUAc3RyaW5nAA0AAABzY2FubGluZWltTU1NTWNhcERhdGUAc0lJSUl0cmluZwATAAAA"
        "MjAyNjoxMToyOCAyMDoxODo1MmNoYW5uZWxzAGNobGlzdACnCAAAYmF0Y2hfbWVhbl9zcS5CLjAAAABTdDlleGNlcHRpb24AAAAA"
        "AAABAAAAAQAAAGJhdGNoX21lYW5fc3EuQi4xAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkIuMgAAAAAAAAAAAAEAAAAB"
        "AAAAYmF0Y2hfbWVhbl9zcS5CLjMAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuQi40AAAAAAAAAAAAAQAAAAEAAABiYXRj"
        "aF9tZWFuX3NxLkIuNQAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5HLjAAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5f"
        "c3EuRy4xAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcuMgAAAAAAAAAAAAEAAAABAAAAYmF0Y2g1AAAAAAAAAAAAAQAA"
        "AAEAAAAAY2h1bmtDb3VudABpbnQABAAAAAEAAABjb21wcmVzc2lvbgBjb21wcmVzc2lvbgABAAAAA2RhdGFXaW5kb3cAYm94MmkA"
        "EAAAAAAAAAAAAAAAAwAAAAMAAABkaXNwbGF5V2luZG93AGJveDJpABAAAAAAAAAAAAAAAAMAAAADAAAAbGluZU9yZGVyAGxpbmVP"
        "cmRlcgABAAAAAG5hbWUAc3RyaW5nAAQAAABmaWxtcGl4ZWxBc3BlY3RSYXRpbwBmbG9hdAAEAAAAAACAP3NjcmVlbldpbmRvd0Nl"
        "bnRlcgB2MmYACAAAAAAAAAAAAAAAc2NyZWVuV2luZG93V2lkdGgAZmxvYXQABAAAAAAAgD90eXBlAHN0cmluZwANAAAAc2Nhbmxp"
        "bmVpbWFnZQAAbg4AAAAAAADhDgAAAAAAAAAAAAAAAAAAZwAAAHheY2hoYGBoAANi6YQFCQuw0M+A1C8sdMMHgQcK2GiG9/WTMGkG"
        "BocDDgew0UAAVIFONzTsdQbpJp7e57TPCQv9LGJFBDa6Yb/jfkds9F7D82ATUem9ziDz9jlhpQ3OO6PRAECQs74BAAAAAAAAALEA"
        "AAB4Xu3VsQ2DMBCF4YzACAyTngUoyAZOOlAUxyiCLngDKFiAPsMwAiNEEY31kM9xcZXvc/f4Oyz59BQUo/dj1X7w+6/AhZZaL1zh"
        "+9TXfY0bJbVeuML3abi+b7hRUuuFK3SfjO6armkfuPsk1Mc+jNz98efRuHsRZymWAjcKd79lW4YbhbsXcS7j+YMbhbtXtppwo3D3"
        "IobRczmXrzvuPty9VWu+5lOFuw93L/7yBX5xQAg="))
    case("merge-found-abort-channel-list-overrun", "-", "error",
         "a partial render whose channel list claims more bytes than the file has (OpenImageIO aborted)",
         args="merge {FILES}/findings/abort-channel-list-overrun.exr -o {CWD}/m.exr", names="abort-channel-list-overrun.exr")
    write("findings/string-attribute-2gb.exr", base64.b64decode(
        "di8xAQIQAABjYXBEYXRlAHN0cmluZwATAAAAMjAyNjoxMToyOCAyMDoxODo1MmNoYW5uZWxzAGNobGlzdACIAgAAQgACAAAAAAAA"
        "AAEAAAABAAAARwACAAAAAAAAAAEAAAABAAAAUgACAAAAAAAAAAEAAAABAAAAdmFyaWFuY2UuQgACAAAAAAAAAAEAAAABAAAAip6N"
        "lpxuY2UuRwACAAAAAAAAAAEAAAABAAAAdmFyaWFuY2UuUgACAAAAAAAAAAEAAAABAAAAAGNodW5rQ291bnQAaW50AAQAAAABAAAA"
        "Y29tcHJlc3Npb24AY29tcHJlc3Npb24AAQAAAANkYXRhV2luZG93AGJveDJpABAAAAAAAAAAAAAAAAMAAAADAAAAZGlzcGxheVdp"
        "bmRvdwBib3gyaQAQAAAAAAAAAAAAAAADAAAAAwAAAGxpbmVPcmRlcgBsaW5lT3JkZXIAAQAAAABuYW1lAHN0cmluZwAFAAAAaW1h"
        "Z2VwYXRoY2w6YmF0Y2hfc3BwAHN0cmluZwACAAAAMTZiYXRjaF9zcHAAc3RyaW5nAAIAAAAxNnBhdGhjbDpiYXRjaGVzAHN0cmlu"
        "ZwABAAAAMXBhdGhjbDpmaWxtX2JhZF9zYW1wbGVzAHN0cmluZwABAAAAMHBhdGhjbDpmaWxtX2JhdGNoZXMAc3RyaW5zdHJpbmcA"
        "AQAAADFwYXRoY2w6cmVsbXNlX2VzdGltYXRlAHN0cmluZwAJAAAAMC4wNzY5MDgycGF0aGNsOnJlbG1zZV9lc3RpbWF0ZV9tZXRo"
        "b2QAc3RyaW5nACEAAABwZXstc2FtcGxlIHZhcmlhbmNlICh1cHBlciBib3VuZClwYXRoY2w6cmVuZGVyX2tleQBzdHJpbmcAmwAA"
        "AHNjZW5lIGU5YmNjYTkxMDdjNmMwMTg7IHNpemUgNHg0OyBzZWVkIDA7IHNhbXBsZXIgc29ib2w7IHN0cmF0ZWd5IG1pczsgYm91"
        "bmMlcyA4OyBzdHJhdGlmaWVkIGJvdW5jZXMgMTsgYmF0Y2ggc3BwIDE2OyBzcHAgNDA7IG9wdGlvbnMgMDAwMDsgc2FtcGxlIGxh"
        "eW91dCAycGF0aGNsOnNhbXBsZV9yYW5nZXMAc3RyaW5nAAUAAHJpbmcABQAAAHNvYm9scGF0aGNsOnNlZWQAc3RyaW5nAAEAAAAw"
        "cGF0aGNsOnNwcABpbnQABAAAABAAAABwYXRoY2w6c3BwX3RvdGFsAHN0cmluZwACAAAANDBwYXRoY2w6c3RvcABzdHJpbmcAAwAA"
        "AHNwcHBpeGVsQXNwZWN0UmF0aW8AZmxvYXQABAAAAAAAgD9zY3JlZW5XaW5kb3dDZW50ZXIAdjJmAAgAAAAAAAAAAAAAAHNjcmVl"
        "bldpbmRvd1dpZHRoAGZsb2F0AAQAAAAAAIA/dHlwZQBzdHJpbmcADQAAAHNjYW5saW5laW1hZ2UAY2FwRGF0ZQBzdHJpbmcAEwAA"
        "ADIwMjY6MTE6MjggMjA6MTg6NTJjaGFubmVscwBjaGxpc3QApwgAAGJhdGNoX21lYW5fc3EuQi4wAAAAAAAAAAAAAQAAAAEAAABi"
        "YXRjaF9tZWFuX3NxLkIuMQAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5CLjIAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21l"
        "YW5fc3EuQi4zAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkIuNAAAAAA/ACoAAAABAAAAAQAAAGJhdGNoX21lYW5fc3Eu"
        "Qi41AAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcuMAAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5HLjEAAAAA"
        "AAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuRy4yAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcuMwAAAAAAAAAAAAEA"
        "AAABAAB2LzEBAhAAAGNhcERhdGUAc3RyaW5nABMAAAAyMDI2OjExOjI4IDIwOjE4OjUyY2huZWxhc24AY2hsaXN0AIgAogAAAAAA"
        "AAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcuNAAAAEcAAgAAAAAAAAAAAAAAAAAAAQAAAAEAAAE="))
    case("merge-found-string-attribute-2gb", "-", "error",
         "a partial render of 1634 bytes whose attribute claims 1.9 GB (OpenEXR allocated it)",
         args="merge {FILES}/findings/string-attribute-2gb.exr -o {CWD}/m.exr", names="string-attribute-2gb.exr")
    # Found by tools/fuzz.sh partial once the headers were walked: OpenEXR 3.1 reads a
    # box2i's 16 bytes whatever byte count it declares, and the attribute it then finds
    # inside the declared 1040 bytes claimed 1.9 GB.
    write("findings/box2i-hides-attribute.exr", base64.b64decode(
        "di8xAQIQAABjYXBEYXRlAHN0cmluZwATAAAAMjAyNjoxMToyOCAyMDoxODo1MmNoYW5uZWxzAGNobGlzdACIAAAAQgACAAAAAAAA"
        "AAEAAAABAAAARwACAAAAAAAAAAEAAAABAAAAUgACAAAAAAAAAAEAAAABAAAAdmFyaWFuY2UuQgACAAAAAAAAAAEAAAABAAAAdmFy"
        "aWFuY2UuRwACAAAAAAAAAAEAAAABAAAAdmFyaWFuY2UuUgACAAAAAAAAAAEAAAABAAAAAGNodW5rQ291bnQAaW50AAQAAAABAAAA"
        "Y29tcHJlc3Npb24AY29tcHJlc3Npb24AAQAAAANkYXRhV2luZG93AGJveDJpABAEAAAAAAAAAAAAAAMAAAADAAAAZGlzcGxheVdp"
        "bmRvdwBib3gyaQAQAAAAAAAAAAAAAAADAAAAAwAAAGxpbmVPcmRlcgBsaW5lT3JkZXIAAQAAAABuYW1lAHN0cmluZwAFAAAAaW1h"
        "Z2VwYXRoY2w6YmF0Y2hfc3BwAHN0cmluZwACAAAAMTZwYXRoY2w6YmF0Y2hlcwBzdHJpbmcAAQAAADFwYXRoY2w6ZmlsbV9iYWRf"
        "c2FtcGxlcwBzdHJpbmcAAQAAADBwYXRoY2w6ZmlsbV9iYXRjaGVzAHN0cmluZwABAAAAMXBhdGhjbDpyZWxtc2VfZXN0aW1hdGUA"
        "c3RyaW5nAAloX21lYW5fc3EuRy4zAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcuNAAAAAAAAAAAAAEAAAABAAAAYmF0"
        "Y2hfbWVhbl9zcS5HLjUAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuUi4wAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFu"
        "X3NxLlIuMQAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5SLjIAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuUi4z"
        "AAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLlIuNAAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5SLjUAAAAAAAAA"
        "AAABAAAAAQAAAGJhdGNoX21lYW5fc3VtLkIuMAAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zdW0uQi4xAAAAAAAAAAAAAQAA"
        "AAEAAABiYXRjaF9tZWFuX3N1bS5CLjMAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3VtLkIuMwAAAAAAAAAAAAEAAAABAAAA"
        "YmF0Y2hfbWVhbl9zdW0uQi40AAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3N1bS5CLjUAAAAAAAAAAAABAAAAAQAAAGJhdGNo"
        "X21lYW5fc3VtLkcuMAAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfZWVhbl9zdW0uRy4xAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFu"
        "X3N1bS5HLjIAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3VtLkcuMwAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zdW0u"
        "Ry40AAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3N1bS5HLjUAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3VtLlIuMAAA"
        "AAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zdW0uUi4xAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3N1bS5SLjIAAAAAAAAA"
        "AAABAAAAAQAAAGJhdGNoX21lYW5fc3VtLlIuMwAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zdW0uUi40AAAAAAAAAAAAAQAA"
        "AAEAAABiYXRjaF9tZWFuX3N1bS5SLjUAAAAAAAAAAAABAAAAAQAAAHBpeGVsX2JhdGNoZXMAAAAAAAAAAAABAAAAAQAAAHNhbXBs"
        "ZXMAAAAAAAAAAAABAAAAAQAAAHN1bS5CLjAAAAAAAAAAAAABAAAAAQAAAHN1bS5CLjEAAAAAAAAAAAABAAAAAQAAAHN1bS5CLjIA"
        "AAAAAAAAAAABAAAAAQAAAHN1bS5CLjMAAAAAAAAAAAABAAAAAQAAAHN1bS5CNC4AAAAAAAAAAAABAAAAAQAAAHN1bS5CLjUAAAAA"
        "AAAAAAABAAAAAQAAAHN1bS5HLjAAAAAAAAAAAAABAAAAAQAAAHN1bS5HLjEAAAAAAAAAAAABAAAAAQAAAHN1bS5HLjIAAAAAAAAA"
        "AAABAAAAAQAAAHN1bS5HLjMAAAAAAAAAAAABAAAAAQAAAHN1bS5HLjQAAAAAAAAAAAABAAAAAQAAAHN1bS5HLjUAAAAAAAAAAAAB"
        "AAAAAQAAAHN1bS5SLjAAAAAAAAAAAAABAAAAAQAAAHN1bS5SLjEAAAAAAAAAAAABAAAAAQAAAHN1bS5SLjIAAAAAAAAAAAABAAAA"
        "AQAAAHN1bS5SLjMAAAAAAAAAAAABAAAAAQAAAHN1bS5SLjQAAAAAAAAAAAABAAAAAQAAAHN1bS5SLjUAAAAAAAAAAAABAAAAAQAA"
        "AHN1bV9zcS5CLjAAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5CLjEAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5CLjIAAAAAAAAAAAAB"
        "AAAAAQAAAHN1bV9zcS5CLjMAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5CLjQAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5CLjUAAAAA"
        "AAAAAAABAAAAAQAAAHN1bV9zcS5HLjAAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5HLjAAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5H"
        "LjIAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5HLjMAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5HLjQAAAAAAAAAAAABAAAAAQAAAHN1"
        "bV9zcS5HLjUAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5SLjAAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5SLjEAAAAAAAAAAAABAAAA"
        "AQAAAHN1bV9zcS5SLjIAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5SLjMAAAAAAAAAAAABAAAAAQAAAHN1bV9zcS5SLjQAAAAAAAAA"
        "AAABAAAAAQAAAHN1bV9zcS5SLjUAAAAAAAAAAAABAAAAbGluZU9yZGVyAAEAAAAAbmFtZQBzdHJpbmcABAAAAGZpbG1waXhlbEFz"
        "cGVjdFJhdGlvAGZsb2F0AAQAAAAAAIA/c2NyZWVuV2luZG93Q2VudGVyAHYyZgAIAAAAAAAAAAAAAABzY3JlZW5XaW5kb3dXaWR0"
        "aABmbG9hdAAEAAAAAACAP3R5cGUAc3RyaW5nAA0AAABzY2FubGluZWltYWdlAABuDgAAAAAAAOEOAAAAAAAAAAAAAAAAAABnAAAA"
        "eF5jaGhgYGgAA2LphAUJC7DQz4DULyx0wweBBwrYaIb39ZMwaQYGhwMOB7DRQABUgU43NOx1Bukmnt7ntM8JC/0sYkUENrphv+N+"
        "R2z0XsPzYBNR6b3OIPP2OWGlDc47o9EAQJCzvgEAAAAAAAAAsQAAAHhe7dWxDYMwEIXhjMAIDJOeBSjIBk46UBTHKIIueAMoWIA+"
        "wzACI0QRjfWQz3Fxle9z9/g7LPn0FBSj92PVfvD7r8CFllovXOH71Nd9jRsltV64wvdpuL5vuFFS64UrdJ+M7pquaR+4+2z0XsPz"
        "YBNR6b3OIPP2OWGlDc47o9EAQJCzvgEAAAAAAAAAsQAAAHhe7dWxDYMwEIXhjMAIDJOeBSjIBk46UBTHKIIueAMoWIA+wzACI0QR"
        "jfWQz3Fxle9z9/g7LPn0FBSj92PVfvD7r8CFllovXOH71Nd9jRsltV64wvdpuL5vuFFS64UrdJ+M7pquaR+4+yTUxz6M3P3x59G4"
        "exFnKZYCNwp3v2VbhhuFuxdxLuP5gxuFu1e2mnCjcPcihtFzOZevO+4+3L1Va77mU4W7D3cv/vIFfnFACA=="))
    case("merge-found-box2i-hides-attribute", "-", "error",
         "a partial render whose dataWindow declares 1040 bytes, inside which a string attribute claims 1.9 GB",
         args="merge {FILES}/findings/box2i-hides-attribute.exr -o {CWD}/m.exr", names="box2i-hides-attribute.exr")
    # And after those: a partial render with unknown version flags, which OpenEXR refuses,
    # after which OpenImageIO 2.4 tried every reader it has, and its RLA reader aborted.
    write("findings/abort-rla-reader.exr", base64.b64decode(
        "di8xAQIQc3EuRy4yAAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcuMwAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9z"
        "cS5HLjQAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuRy41tJbwW9HXoq+F32LQTXVNdW+x0DMynfa9waCb6mSfbPTHpAGv"
        "prW+AQAAAAAAAAC7AAAAeF5jaBgK+EBTHQTOyHYvMQECEAAAY2FwRGF0ZQBzdHJpbmcAEwAAADIwMjY6MTE6MjggMjA6MTg6NTJj"
        "aGFubmVscwBjaAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcuNbSW8FvR16Kvhd9i0E11TXVvsdAzMp32vcGgm+pkn2z0x6QB"
        "r6a1vgEAAAAAAAAAuwAAAHheY2gYCvhAUx0Ezsh2LzEBAhAAAGNhcERhdGUAc3RyaW5nABMAAAAyMDI2OjExOjI4IDIwOjE4OjUy"
        "Y2hhbm5lbHMAY2hsaQAAY2FwRGF0ZQBzdHJpbmcAEwAAADIwMjY6MTE6MjggMjA6MzY6NDVjaGFubmVscwBjaGxpc3QAiAAAAEIA"
        "AgAAAAAAAAABAAAAAQAAAEcAAgAAAAAAAAABAAAAAQAAAFIAAgAAAAAAAAABAAAAAQAAAHZhcmlhbmNlLkIAAgAAAAAAAAABAAAA"
        "AQAAAHZhcmlhbmNlLkcAAgAAAAAAAAABAAAAAQAAAHZhcmlhbmNlLlIAAgAAAAAAAAABAAAAAQAAAABjaHVua0NvdW50AGludAAE"
        "AAAAAQAAAGNvbXByZXNzaW9uAGNvbXByZXNzaW9uAAEAAAADZGF0YVdpbmRvdwBib3gyaQAQAAAAAAAAAAAAAAADAAAAAwAAAGRp"
        "c3BsYXlXaW5kb3cAYm94MmkAEAAAAAAAAAAAAAAAAwAAAAMAAABsaW5lT3JkZXIAbGluZU9yZGVyAAEAAAAAbmFtZQBzdHJpbmcA"
        "BQAAAGltYWdlcGF0aGNsOmJhdGNoX3NwcABzdHJpbmcAAgAAADU2cGF0aGNsOmJhdGNNTU1NaGVzAHN0cmluZwABAAAAMnBhdGhj"
        "bDpmaWxtX2JhZF9zYW1wbGVzAHN0cmluZwABAAAAMHBhOjI4IDIwOjM2OjQ1Y2hhbkFlbHMAY2hsaXN0AKcIAABiYXRjaF9tZWFu"
        "X3NxLkIsMAAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5CLjEAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuQi4y"
        "AAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkIuMwAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5CLjQAAAAAAAAA"
        "AAABAAAAAQAAAGJhdGNoX21lYW5fc3EuQi41AAAAAAAAAAAAAQAAAAEAAABiYXRjaF9tZWFuX3NxLkcuMAAAAAAAAAAAAAEAAAAB"
        "AAAAYmF0Y2hfbWVhbl9zcS5HLjEAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5fc3EuRy4yAAAAAAAAAAAAAQAAAAEAAABiYXRj"
        "aF9tZWFuX3NxLkcuMwAAAAAAAAAAAAEAAAABAAAAYmF0Y2hfbWVhbl9zcS5HLjQAAAAAAAAAAAABAAAAAQAAAGJhdGNoX21lYW5f"
        "c3EuRy41tJbwW9HXoq+F32LQTXVNdW+x0DMynfa9waCb6mSfbPTHpAGvprW+AQAAAAAAAAC7AAAAeF5jaBgK+EBTHQTOyHYvMQEC"
        "EAAAY2FwRGF0ZQBzdHJpbmcAEwAAADIwMjY6MTE6MjggMjA6MTg6NTJjaGFubmVscwBjaAAAAAAAAQAAAAEAAABiYXRjaF9tZWFu"
        "X3NxLkcuNbSW8FvR16Kvhd9i0E11TXVvsdAzMp32vcGgm+pkn2z0x6QBr6a1vgEAAAAAAAAAuwAAAHheY2gYCvhAUx0Ezsh2LzEB"
        "AhAAAGNhcERhdGUAc3RyaW5nABMAAAAyMDI2OjExOjI4IDIwOjE4OjUyY2hhbm5lbHMAY2hsaXN0AIgAAABCAAIAAAAAAAAAAQAA"
        "AAEAAABHAAIAAAAAAAAAAQAAAAEAAABSAAIAAAAAAAAAAQAAAAEAAAB2YXJpYW5jZS5CAAIAAAAAAAAAAQAAAAEAAAB2YXJpYW5j"
        "ZS5HAAIAAAAAAAAAAQAAAAEAAAB2YXJpYW5jZS5SAAIAAAAAAAAAAQAAAAEAAAAAY2h1bmtDb3VudABpbnQABAAAAAEAAABjb21w"
        "cmVzc2lvbgBjb21wcmVzc2lvbgABAAAAA2RhdGFXaW5kb3cAYm94MmkAEAAAAIBAdPmGhsZ6dBH8YKSpHwXIgHB66irrLkUXwwdG"
        "mvrGetJS4PBWTyg9NdZPy5qWhc8EVDDS1I8CVEAoAAAAAAAAAAADAAAAAwAAAGRpc3BsYXlXaW5kb3cAYm/19fX19T011XWVdZYT"
        "H74jSD1RipAA9fX19fX19fX19fX19fX19a3VTyhA"))
    case("merge-found-abort-rla-reader", "-", "error",
         "a partial render with unknown EXR version flags (OpenImageIO's RLA reader aborted on it)",
         args="merge {FILES}/findings/abort-rla-reader.exr -o {CWD}/m.exr", names="abort-rla-reader.exr")
    case("merge-not-partial", "-", "error", "merge of an EXR that is no partial render (an environment map)",
         args="merge {FILES}/env/valid.exr -o {CWD}/m.exr", names="valid.exr")
    case("merge-output-is-input", "-", "error", "merge whose output is one of its inputs, spelled otherwise",
         args="merge {FILES}/partial/a.exr {FILES}/partial/b.exr -o {FILES}/partial/../partial/a.exr", setup=two,
         names="a.exr")
    case("merge-output-fifo", "-", "error", "merge onto a FIFO (it must stay a FIFO)",
         args="merge {FILES}/partial/a.exr {FILES}/partial/b.exr -o {FILES}/partial/out-fifo.exr",
         setup=two + ",mkfifo:partial/out-fifo.exr", names="out-fifo.exr")
    case("merge-input-fifo", "-", "error", "merge of a FIFO",
         args="merge {FILES}/partial/in-fifo.exr -o {CWD}/m.exr", setup="mkfifo:partial/in-fifo.exr",
         names="in-fifo.exr")

    # Outputs: special files, one file under two names, where nothing can be written.
    case("output-fifo", "valid.gltf", "error", "-o naming a FIFO (it must stay a FIFO)",
         args="-o {FILES}/out-fifo.exr", setup="mkfifo:out-fifo.exr", names="out-fifo.exr")
    case("checkpoint-output-fifo", "valid.gltf", "error", "--checkpoint naming a FIFO",
         args="--checkpoint {FILES}/cp-fifo.bin", setup="mkfifo:cp-fifo.bin", names="cp-fifo.bin")
    case("ray-log-fifo", "valid.gltf", "error", "--ray-log naming a FIFO",
         args="--ray-log {FILES}/rays-fifo.ply", setup="mkfifo:rays-fifo.ply", names="rays-fifo.ply")
    case("checkpoint-is-the-output", "valid.gltf", "error", "--checkpoint ./out.png beside -o {CWD}/out.png",
         args="--checkpoint ./out.png", names="out.png")
    case("ray-log-is-the-checkpoint", "valid.gltf", "error", "--ray-log r.ply and --checkpoint ./r.ply",
         args="--ray-log {CWD}/r.ply --checkpoint ./r.ply", names="r.ply")
    case("resume-is-the-output", "valid.gltf", "error", "-o cp.exr --resume ./cp.exr (the checkpoint overwritten)",
         args="-o {CWD}/cp.exr --resume ./cp.exr", names="cp.exr")
    case("checkpoint-is-the-scene", "valid.gltf", "error", "--checkpoint naming the scene file",
         args="--checkpoint {SCENE}", names="valid.gltf")
    case("checkpoint-unwritable", "valid.gltf", "error",
         "--checkpoint where no file can be written (found before the render, not at its first checkpoint)",
         args="--checkpoint {RO}/cp.bin", names="cp.bin")

    # Small inputs, unbounded work.
    m = base()
    m["extensionsUsed"].append("EXT_mesh_gpu_instancing")
    m["accessors"].append({"componentType": 5126, "count": 10000000, "type": "VEC3"})
    m["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": 3}}}
    model_case("ext/instancing-1e7-coincident.gltf", "bomb-instances-1e7", "error",
               "10^7 coincident instances from a TRANSLATION accessor without bufferView", m)
    m = base()
    m["materials"][0]["emissiveFactor"] = [0.0, 0.0, 0.0]  # drawn twice, an instanced mesh (emitters are copied)
    m["nodes"][0]["translation"] = [2e38, 0.0, 0.0]
    m["nodes"].append({"name": "again", "mesh": 0})
    m["scenes"][0]["nodes"].append(2)
    model_case("node/instance-translated-2e38.gltf", "node-instance-beyond-float", "error",
               "a mesh drawn by two nodes, one translated by 2e38 (render-space bounds overflow float)", m)
    m = base()
    m["extensionsUsed"].append("KHR_materials_variants")
    m["extensions"] = {"KHR_materials_variants": {"variants": [{"name": "a"}]}}
    m["meshes"][0]["primitives"][0]["extensions"] = {
        "KHR_materials_variants": {"mappings": [{"material": 0, "variants": [424242]}]}}
    model_case("ext/variant-index-2p32.gltf", "ext-variant-index-2p32", "error",
               "a KHR_materials_variants mapping's variant index 2^32 (0 after a 32-bit wrap)", m,
               raw=("424242", "4294967296"))
    many = lambda knob: "--vary " + knob + "=" + ",".join(str(i) for i in range(2000))
    case("bomb-converge-plan", "-", "error", "converge of 2000 x 2000 settings (4,000,000 kernel builds)",
         args="converge {FILES}/valid.gltf -o {CWD}/study " + many("max-bounces") + " " + many("stratified-bounces"),
         names="4000000 settings")
    case("bomb-film-32768", "valid.gltf", "error", "--width 32768 --height 32768 (a 432 GiB film)",
         args="--width 32768 --height 32768", names="the film needs")
    case("converge-ladder-falling", "-", "error", "converge --spp-ladder 4,2,1",
         args="converge {FILES}/valid.gltf -o {CWD}/study --vary strategy=mis --spp-ladder 4,2,1",
         names="--spp-ladder")
    case("converge-ladder-empty-step", "-", "error", "converge --spp-ladder 1,,2",
         args="converge {FILES}/valid.gltf -o {CWD}/study --vary strategy=mis --spp-ladder 1,,2",
         names="--spp-ladder")
    case("converge-targets-nan", "-", "error", "converge --targets nan",
         args="converge {FILES}/valid.gltf -o {CWD}/study --vary strategy=mis --targets nan", names="--targets")

    # Argument lists for tools/fuzz.sh cli (not cases: seeds of the fuzzer).
    args_file("cli-args/render.args", ["render", "scene.gltf", "-o", "out.exr", "--width", "8", "--height", "8",
                                       "--spp", "4", "--sampler", "halton", "--background", "1,1,1"])
    args_file("cli-args/render-budget.args", ["render", "scene.gltf", "-o", "out.png", "--time", "2", "--max-spp",
                                              "64", "--batch-spp", "16", "--checkpoint", "cp.bin"])
    args_file("cli-args/render-range.args", ["render", "scene.gltf", "-o", "r.exr", "--spp", "64", "--batch-spp",
                                             "16", "--sample-range", "16:32", "--seed", "3"])
    args_file("cli-args/converge.args", ["converge", "scene.gltf", "-o", "study", "--vary", "sampler=sobol,halton",
                                         "--spp-ladder", "1,2,4", "--targets", "0.01,0.001"])
    args_file("cli-args/merge.args", ["merge", "a.exr", "b.exr", "-o", "m.exr"])
    args_file("cli-args/samples.args", ["samples", "--sampler", "sobol", "--spp", "64", "-o", "points.png"])
    args_file("cli-args/info.args", ["info", "scene.gltf", "--variant", "a"])


def main():
    if os.path.isdir(FILES):
        shutil.rmtree(FILES)
    os.makedirs(FILES)
    valid_scenes()
    json_cases()
    glb_cases()
    accessor_cases()
    node_cases()
    camera_cases()
    light_cases()
    material_cases()
    extension_cases()
    uri_cases()
    image_cases()
    environment_cases()
    cli_cases()
    service_cases()
    largest = max((os.path.getsize(os.path.join(d, f)), os.path.join(d, f))
                  for d, _, fs in os.walk(FILES) for f in fs)
    assert largest[0] < 1 << 20, largest
    with open(os.path.join(HERE, "expected.tsv"), "w") as f:
        f.write("# name\tfile\targs\texpect\tsetup\tnames\twhat (written by make_corpus.py)\n")
        for c in CASES:
            f.write("\t".join(c) + "\n")
    print("make_corpus: %d cases (%d file cases, %d CLI cases); largest file %d bytes (%s)" %
          (len(CASES), len(CASES) - CLI_CASES, CLI_CASES, largest[0], os.path.relpath(largest[1], HERE)))


if __name__ == "__main__":
    sys.exit(main())
