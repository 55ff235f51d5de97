#!/usr/bin/env python3
"""Writes copies of a scene with its directional shadows and its SSAO turned on or off, so the
docs images and the cost measurements compare the same scene with and without them.

Usage: scripts/shadow-scene-variants.py SCENE OUT_DIR
Writes OUT_DIR/{plain,shadows,ssao,both}.json (paths inside stay valid: only the two
settings change, and the scenes used here name no files)."""
import json
import os
import sys

source, out_dir = sys.argv[1], sys.argv[2]
with open(source) as f:
    scene = json.load(f)
os.makedirs(out_dir, exist_ok=True)
for name, shadows, ssao in [("plain", False, False), ("shadows", True, False), ("ssao", False, True),
                            ("both", True, True)]:
    variant = json.loads(json.dumps(scene))
    if "directional" in variant:
        variant["directional"]["shadows"] = shadows
    variant.setdefault("ssao", {})["enabled"] = ssao
    with open(os.path.join(out_dir, name + ".json"), "w") as f:
        json.dump(variant, f, indent=1)
