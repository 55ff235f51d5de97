#!/usr/bin/env python3
"""Writes scenes/glass.json: bench/courtyard.json (its buildings, plaza, fountain and 1,024
point lights) with transparent things in the plaza, the example of docs/transparency.md:
four coloured glass panes around the fountain and a fountain of translucent spheres falling
from its top into the basin in six arcs, and a camera over the plaza.

Usage: scripts/make-glass-scene.py   (from the repository root; rewrites scenes/glass.json)
"""
import json
import math
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def main():
    scene = json.loads((ROOT / "bench/courtyard.json").read_text())
    scene["camera"] = {"eye": [1.5, 3.4, 6.2], "look_at": [0, 1.5, -0.5], "up": [0, 1, 0], "fov_y": 55,
                       "near": 0.2, "far": 120}
    # Lamps around the basin at the drops' and panes' height, among the courtyard's lights.
    scene["lights"] = [{"type": "point", "pos": [round(3.4 * math.sin(math.radians(60 * k)), 3), 1.6 + 0.8 * (k % 2),
                                                 round(3.4 * math.cos(math.radians(60 * k)), 3)],
                        "intensity": [4 * c for c in colour], "range": 4.5}
                       for k, colour in enumerate([[1.0, 0.8, 0.5], [0.5, 0.7, 1.0], [0.9, 0.5, 0.8],
                                                   [0.6, 1.0, 0.6], [1.0, 0.6, 0.4], [0.7, 0.7, 1.0]])]
    materials = scene["materials"]
    panes = {"blue glass": [0.25, 0.45, 0.9], "green glass": [0.3, 0.8, 0.4],
             "amber glass": [0.95, 0.6, 0.15], "rose glass": [0.9, 0.3, 0.5]}
    for name, colour in panes.items():
        materials[name] = {"diffuse": colour, "specular": [0.6, 0.6, 0.6], "shininess": 96, "opacity": 0.4}
    materials["water"] = {"diffuse": [0.45, 0.75, 0.95], "specular": [0.8, 0.8, 0.8], "shininess": 64,
                          "opacity": 0.5}
    objects = scene["objects"]
    # Panes standing on the plaza, each facing the fountain, a quarter turn apart.
    for k, name in enumerate(panes):
        angle = math.radians(45 + 90 * k)
        objects.append({"name": f"pane {k}", "mesh": {"primitive": "box", "size": [3.0, 2.4, 0.08]},
                        "material": name,
                        "transform": {"translate": [round(5.0 * math.sin(angle), 3), 1.3,
                                                    round(5.0 * math.cos(angle), 3)],
                                      "rotate": [0, round(math.degrees(angle), 3), 0]}})
    # Six arcs of falling drops: from the top of the pillar (0, 3.5, 0) out to the basin's rim.
    for arc in range(6):
        heading = math.radians(60 * arc + 30)
        for step in range(1, 6):
            t = step / 5.0
            reach = 2.2 * t
            height = 3.5 + 1.2 * t - 3.0 * t * t
            objects.append({"name": f"drop {arc}.{step}",
                            "mesh": {"primitive": "sphere", "radius": round(0.3 - 0.03 * step, 3)},
                            "material": "water",
                            "transform": {"translate": [round(reach * math.sin(heading), 3), round(height, 3),
                                                        round(reach * math.cos(heading), 3)]}})
    text = json.dumps(scene, indent=None)
    # One object per line, as the courtyard file is laid out.
    text = text.replace('{"name"', '\n    {"name"')
    (ROOT / "scenes/glass.json").write_text(text + "\n")


if __name__ == "__main__":
    main()
