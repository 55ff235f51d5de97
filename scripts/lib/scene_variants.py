#!/usr/bin/env python3
"""Scenes that the measure scripts derive from the project's own (docs/performance.md): each
subcommand reads a scene file and writes a variant of it, with model paths made absolute so that
the variant may live anywhere.

    scene_variants.py environment SCENE WITHOUT.json WITH.json   without its environment, with builtin:studio
    scene_variants.py shininess SCENE OUT.json [--offset D] [--replace S=T,...]
    scene_variants.py metallic-roughness SCENE OUT.json          Blinn-Phong materials as metallic-roughness
    scene_variants.py drop-objects SCENE OUT.json PREFIX         without the objects whose name starts so
    scene_variants.py light-grid N OUT.json                      N point lights over a plane, inline
    scene_variants.py hdr-map OUT.hdr                            a 1024x512 Radiance map: smooth, a few bright patches
"""

import argparse
import json
import math
import os


def load(path):
    with open(path) as f:
        scene = json.load(f)
    # Model paths stay relative to the original scene's folder.
    base = os.path.dirname(os.path.abspath(path))
    for obj in scene.get("objects", []):
        if isinstance(obj.get("mesh"), str):
            obj["mesh"] = os.path.join(base, obj["mesh"])
    return scene


def save(scene, path):
    with open(path, "w") as f:
        json.dump(scene, f)


def environment(args):
    scene = load(args.scene)
    scene.pop("environment", None)
    save(scene, args.without)
    # Not shown as the background, so that only the lighting differs.
    scene["environment"] = {"map": "builtin:studio"}
    save(scene, args.with_)


def shininess(args):
    scene = load(args.scene)
    # Whole numbers stay integers in the file: an integer shininess is raised by multiplications.
    number = lambda text: int(text) if float(text).is_integer() else float(text)
    replace = {}
    for pair in filter(None, (args.replace or "").split(",")):
        old, new = pair.split("=")
        replace[number(old)] = number(new)
    for material in scene["materials"].values():
        if "shininess" in material:
            value = replace.get(material["shininess"], material["shininess"])
            material["shininess"] = value + args.offset if args.offset else value
    save(scene, args.out)


def metallic_roughness(args):
    """base_color = diffuse, metallic 0, roughness (2 / (s + 2))^(1/4): the roughness whose
    Blinn-Phong exponent is s; a material whose specular outweighs its diffuse a metal of base
    colour its specular."""
    scene = load(args.scene)
    for name, material in scene["materials"].items():
        diffuse = material.get("diffuse", [0.8, 0.8, 0.8])
        specular = material.get("specular", [0, 0, 0])
        exponent = material.get("shininess", 32)
        metal = max(specular) > max(diffuse)
        scene["materials"][name] = {
            "base_color": specular if metal else diffuse,
            "metallic": 1 if metal else 0,
            "roughness": round((2.0 / (exponent + 2.0)) ** 0.25, 4) if max(specular) > 0 else 1,
        }
    save(scene, args.out)


def drop_objects(args):
    scene = load(args.scene)
    scene["objects"] = [o for o in scene["objects"] if not o.get("name", "").startswith(args.prefix)]
    save(scene, args.out)


def light_grid(args):
    lights = [{"type": "point", "pos": [i % 100, 1, i // 100 % 100], "intensity": [1, 1, 1], "range": 1}
              for i in range(args.count)]
    save({"lights": lights, "objects": [{"mesh": {"primitive": "plane", "size": [10, 10]}}]}, args.out)


def hdr_map(args):
    """Flat (unencoded) RGBE scanlines."""
    width, height = 1024, 512
    with open(args.out, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width))
        for j in range(height):
            theta = math.pi * (j + 0.5) / height
            row = bytearray()
            for i in range(width):
                phi = 2 * math.pi * (i + 0.5) / width
                value = [0.5 + 0.3 * math.cos(theta) + 0.1 * math.sin(5 * phi) * math.sin(3 * theta)] * 3
                if math.cos(theta) > 0.7 and math.sin(3 * phi) > 0.8:
                    value = [12.0, 11.0, 9.0]
                largest = max(value)
                mantissa, exponent = math.frexp(largest)
                scale = mantissa * 256.0 / largest
                row += bytes([int(c * scale) for c in value] + [exponent + 128])
            f.write(bytes(row))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    p = commands.add_parser("environment")
    p.add_argument("scene")
    p.add_argument("without")
    p.add_argument("with_", metavar="with")
    p.set_defaults(run=environment)
    p = commands.add_parser("shininess")
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--offset", type=float, default=0.0)
    p.add_argument("--replace", help="S=T,... : shininess S becomes T")
    p.set_defaults(run=shininess)
    p = commands.add_parser("metallic-roughness")
    p.add_argument("scene")
    p.add_argument("out")
    p.set_defaults(run=metallic_roughness)
    p = commands.add_parser("drop-objects")
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("prefix")
    p.set_defaults(run=drop_objects)
    p = commands.add_parser("light-grid")
    p.add_argument("count", type=int)
    p.add_argument("out")
    p.set_defaults(run=light_grid)
    p = commands.add_parser("hdr-map")
    p.add_argument("out")
    p.set_defaults(run=hdr_map)
    args = parser.parse_args()
    args.run(args)


if __name__ == "__main__":
    main()
