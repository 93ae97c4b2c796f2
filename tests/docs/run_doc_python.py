# SPDX-License-Identifier: Apache-2.0
"""Runs every ```python block of a Markdown file, in order, in one namespace, in a scratch
folder holding the sample files the docs name (the way run_doc_commands.sh runs the
shell commands). Sizes of 2048 and 1024 run at 512 and 256 to keep CI short: the code
path is the same.

usage: /usr/bin/python3 run_doc_python.py REPO_DIR DOC.md WORK_DIR   (texsyn importable)
"""
import os
import re
import shutil
import sys

repo, doc, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
samples = os.path.join(repo, "data", "samples")
for name, source in (("rust.png", "rust.png"), ("marble.png", "marble_pink.png"),
                     ("bricks.png", "bricks.png"), ("bricks_height.png", "bricks_height.png"),
                     ("bricks_normal.png", "bricks_normal.png")):
    shutil.copy(os.path.join(samples, source), os.path.join(work, name))
os.chdir(work)
os.environ.pop("OCIO", None)

with open(doc, encoding="utf-8") as f:
    blocks = re.findall(r"^```python\n(.*?)^```", f.read(), re.M | re.S)
namespace = {}
for i, block in enumerate(blocks):
    print(f"+ block {i + 1}")
    block = block.replace("2048", "512").replace("1024", "256")
    exec(compile(block, f"{os.path.basename(doc)} block {i + 1}", "exec"), namespace)
print(f"{len(blocks)} Python blocks from {os.path.basename(doc)} ran")
if not blocks:
    sys.exit("no ```python blocks found")
