# SPDX-License-Identifier: Apache-2.0
# docs/recipe.schema.json validates what texsyn reads and writes: the recipes in
# docs/recipes.md, recipes that `texsyn --recipe` writes for every method, and good and bad
# examples, each bad one for the reason given. (recipe_test checks the schema against the
# option tables.)
# usage: check_recipe_schema.py TEXSYN_EXE REPO_DIR WORK_DIR
import json
import os
import re
import shutil
import subprocess
import sys

import jsonschema

texsyn, repo, work = (os.path.abspath(a) for a in sys.argv[1:4])
with open(os.path.join(repo, "docs", "recipe.schema.json")) as f:
    schema = json.load(f)
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
failures = []
checked = 0


def check(name, recipe, valid):
    global checked
    checked += 1
    errors = list(validator.iter_errors(recipe))
    if valid and errors:
        failures.append(f"{name}: should validate, but: {errors[0].message}")
    if not valid and not errors:
        failures.append(f"{name}: should not validate")


with open(os.path.join(repo, "docs", "recipes.md")) as f:
    for i, block in enumerate(re.findall(r"```json\n(.*?)```", f.read(), re.S)):
        check(f"docs/recipes.md json block {i}", json.loads(block), True)

# Recipes as the tool writes them.
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
shutil.copy(os.path.join(repo, "data", "samples", "stucco_yellow.png"), work)
env = dict(os.environ, OCIO="")
subprocess.run([texsyn, "stucco_yellow.png", "--analyze", "-o", "stucco.tsa"], cwd=work, env=env,
               check=True)
for method, inputs, modifiers, out in [
    ("pyramid", ["stucco_yellow.png"], "size=32x32:iterations=1:gain=1.5", "out.exr"),
    ("pyramid", ["stucco.tsa"], "size=32x32:iterations=1", "out.exr"),
    ("neighborhood", ["stucco_yellow.png"], "size=16x16:levels=1:n=3:search=exhaustive:eps=0.5",
     "out.exr"),
    ("choosy", ["stucco_yellow.png"],
     "size=16x16:levels=2:iterations=1,2:search=exhaustive:penalty=0.5", "out.exr"),
    ("patch", ["stucco_yellow.png"], "size=24x24:patch=7,5:repetition=1", "out.exr"),
    ("solid", ["stucco_yellow.png"], "size=16x16x8:iterations=1", "out.vdb"),
    ("mix", ["stucco_yellow.png", "stucco.tsa"], "palette=0:pattern=1:size=32x32:iterations=1",
     "out.exr"),
    ("transfer", ["stucco_yellow.png", "stucco.tsa"], "iterations=1", "out.exr"),
    ("cascade", [], "preset=cells:size=32x32", "out.exr"),
    ("cascade", ["stucco_yellow.png"], "levels=2:palette=stucco_yellow.png", "out.exr"),
]:
    name = f"{method}_{len(inputs)}"
    subprocess.run([texsyn, *inputs, f"--{method}:{modifiers}", "-o", out,
                    "--recipe", f"{name}.texsyn"], cwd=work, env=env, check=True)
    with open(os.path.join(work, f"{name}.texsyn")) as f:
        check(f"texsyn {' '.join(inputs)} --{method} --recipe", json.load(f), True)

good = {
    "minimal": {"sample": "a.png"},
    "pyramid by name": {"sample": "a.png", "method": "pyramid", "size": [64, 32],
                        "gain": [1, 1.5], "subbands": True},
    "pyramid from an analysis": {"sample": "a.tsa", "size": "64x64"},
    "neighborhood": {"sample": "a.png", "method": "neighborhood", "size": "64x64", "levels": 2,
                     "n": "7,5", "search": "exhaustive", "eps": 0.5, "subbands": False},
    "neighborhood n as a number": {"sample": "a.png", "method": "neighborhood", "n": 9},
    "neighborhood n as an array": {"sample": "a.png", "method": "neighborhood", "n": [9, 7]},
    "choosy": {"sample": "a.png", "method": "choosy", "size": "64x64", "levels": 3,
               "iterations": "1,8", "penalty": 0.5, "isotropic": 0, "search": "kdtree",
               "dims": 12, "eps": 0.5, "subbands": False},
    "choosy iterations as a number": {"sample": "a.png", "method": "choosy", "iterations": 2},
    "choosy iterations as an array": {"sample": "a.png", "method": "choosy",
                                      "iterations": [1, 8]},
    "solid": {"sample": "a.png", "method": "solid", "size": [32, 32, 16]},
    "mix of an image and an analysis": {"sample": ["a.png", "b.tsa"], "method": "mix",
                                        "palette": 0, "pattern": 1,
                                        "iscolorspace": ["sRGB", ""]},
    "mix by weights": {"sample": ["a.png", "b.png", "c.png"], "method": "mix",
                       "weights": "1,1,2"},
    "transfer": {"sample": ["photo.png", "rust.tsa"], "method": "transfer", "iterations": 2},
    "cascade generator": {"method": "cascade", "preset": "stone", "size": [64, 64]},
    "cascade with files": {"method": "cascade", "sample": "a.png", "dilation": "ctrl.exr",
                           "kernel": "gauss5,aniso7", "levels": 2},
}
bad = {
    "no sample": {"size": "8x8"},
    "unknown key": {"sample": "a.png", "octaves": 3},
    "unknown method": {"sample": "a.png", "method": "quilting"},
    "a neighborhood option without the method": {"sample": "a.png", "levels": 2},
    "a neighborhood option for the pyramid": {"sample": "a.png", "method": "pyramid", "n": 9},
    "a pyramid option for the neighborhood": {"sample": "a.png", "method": "neighborhood",
                                              "iterations": 2},
    "neighborhood subbands": {"sample": "a.png", "method": "neighborhood", "subbands": True},
    "neighborhood from an analysis": {"sample": "a.TSA", "method": "neighborhood"},
    "n too small": {"sample": "a.png", "method": "neighborhood", "n": [9, 1]},
    "unknown search": {"sample": "a.png", "method": "neighborhood", "search": "brute"},
    "pyramid iterations as an array": {"sample": "a.png", "iterations": [1, 8]},
    "a neighborhood option for choosy": {"sample": "a.png", "method": "choosy", "n": 9},
    "a choosy option for the neighborhood": {"sample": "a.png", "method": "neighborhood",
                                             "penalty": 1},
    "a choosy option without the method": {"sample": "a.png", "penalty": 1},
    "choosy search of the neighborhood only": {"sample": "a.png", "method": "choosy",
                                               "search": "coherent"},
    "choosy dims=0": {"sample": "a.png", "method": "choosy", "dims": 0},
    "choosy iterations=0": {"sample": "a.png", "method": "choosy", "iterations": [1, 0]},
    "choosy penalty too large": {"sample": "a.png", "method": "choosy", "penalty": 17},
    "choosy subbands": {"sample": "a.png", "method": "choosy", "subbands": True},
    "choosy from an analysis": {"sample": "a.tsa", "method": "choosy"},
    "solid with a 2-D size": {"sample": "a.png", "method": "solid", "size": "32x32"},
    "solid subbands": {"sample": "a.png", "method": "solid", "subbands": True},
    "mix of one sample": {"sample": "a.png", "method": "mix", "palette": 0, "pattern": 1},
    "transfer with a size": {"sample": ["a.png", "b.png"], "method": "transfer", "size": "8x8"},
    "transfer onto an analysis": {"sample": ["a.tsa", "b.png"], "method": "transfer"},
    "cascade with a sample list": {"method": "cascade", "sample": ["a.png", "b.png"]},
    "cascade writes no map": {"method": "cascade", "map": "m.exr"},
    "neighborhood map is the tool's": {"sample": "a.png", "method": "neighborhood",
                                       "map": "m.exr"},
    "cascade unknown kernel": {"method": "cascade", "kernel": "gauss5,plaid"},
}
for name, recipe in good.items():
    check(name, recipe, True)
for name, recipe in bad.items():
    check(name, recipe, False)

for failure in failures:
    print("FAIL", failure)
print(f"{checked - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
