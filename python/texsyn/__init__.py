# SPDX-License-Identifier: Apache-2.0
"""texsyn: texture synthesis for VFX pipelines, on OpenImageIO and OpenColorIO.

One function per method of texsyn's registry (the `texsyn` tool's commands), made from
its option tables when this package is imported: texsyn.pyramid, texsyn.patch, ... .
Images go in and come out as numpy arrays, OpenImageIO.ImageBuf objects or file names.
See docs/python.md; help(texsyn.pyramid) lists a method's keywords.
"""

import inspect as _inspect
import textwrap as _textwrap

from . import _texsyn
from ._texsyn import Analysis, Material, Recipe, Surface, __version__, apply_map

_P = _inspect.Parameter

# Keywords every method takes besides its options.
_COMMON = (
    ("seed", 0, "random seed; the same seed gives the same pixels at any threads="),
    ("threads", 0, "worker threads (0: one per core)"),
    ("max_memory", None, "this run's memory budget: bytes, or a size such as \"2G\" or "
                         "\"512M\"; work needing more is refused before it starts, whatever "
                         "the rest of the process holds (None: texsyn's process-wide limit)"),
    ("progress", None, "a callable taking the fraction done (0..1), called on this thread "
                       "at most every 50 ms and at the end; an exception it raises stops "
                       "the run (Ctrl-C does too)"),
    ("colorconfig", None, "the OCIO config file (None: $OCIO, else texsyn's bundled config)"),
    ("iscolorspace", None, "the inputs' colour space: a name, or a list with one per input "
                           "(None: a file's or ImageBuf's tags; uint8/uint16 arrays sRGB, "
                           "float arrays scene-linear)"),
    ("tocolorspace", None, "the result's colour space (None: scene-linear for float results, "
                           "the input's own for uint8/uint16 ones)"),
)

_IMAGE = ("a numpy array (H x W or H x W x C; uint8, uint16 or float), an "
          "OpenImageIO.ImageBuf, or a file name")

_INPUTS = {
    "none": (),
    "optional_image": (("image", None, "an image to start from: " + _IMAGE),),
    "image": (("image", _P.empty, _IMAGE),),
    "sample": (("sample", _P.empty, _IMAGE + ", or a texsyn.Analysis of one"),),
    "image_and_sample": (("image", _P.empty, _IMAGE),
                         ("sample", _P.empty, _IMAGE + ", or a texsyn.Analysis of one")),
    "samples": (("samples", _P.empty, "a list of samples, each " + _IMAGE
                 + ", or a texsyn.Analysis"),),
}

_RETURNS = {
    "image": "the image, given back as the input was given (array in, array out, H x W "
             "in, H x W out; ImageBuf in, ImageBuf out with its synth:* metadata; a file "
             "name or no input: a float32 array H x W x C)",
    "volume": "the volume: a float32 array D x H x W x C (an ImageBuf with depth D for an "
              "ImageBuf input)",
    "analysis": "a texsyn.Analysis (its .save(path) writes the .tsa file)",
    "report": "the report, as text",
    "mesh": "a texsyn.Surface (vertices, faces, per-face colours, UV bakes, write_ply())",
    "material": "a texsyn.Material, for a copying method ("
                + ", ".join(r["name"] for r in _texsyn._method_table() if r["materials"]) + ")",
}


def _wrap(text, indent):
    return _textwrap.fill(text, 88, initial_indent=indent, subsequent_indent=indent)


def _doc(row):
    lines = [row["summary"], "", _textwrap.fill(row["help"], 88), ""]
    lines.append("Inputs:")
    for name, _, what in _INPUTS[row["inputs"]]:
        lines.append(_wrap(f"{name}: {what}", "    "))
    if row["materials"]:
        lines.append(_wrap("a texsyn.Material, or a dict of maps ({'albedo': ..., "
                           "'height': ..., 'normal': ...}), in place of the image: every "
                           "map is synthesized together", "    "))
    writes = [o for o in row["options"] if o["file"] == "write"]
    returns = _RETURNS[row["output"]]
    if writes:
        returns = ("a tuple: " + returns + ", then "
                   + ", ".join(f"the {o['option']}= image (float32; the tool writes it to "
                               "a file)" for o in writes)
                   + "; for a material set, a dict of maps by name first")
    if row["subbands"]:
        returns += ("; with subbands=True, a tuple of it and a dict of the sample's and the "
                    "synthesis's pyramid subbands (float32 arrays of the decorrelated "
                    "components, named as the parts of `texsyn --subbands`, docs/subbands.md)")
    lines += ["", "Returns:", _wrap(returns, "    "), ""]
    lines.append(f"Options (those of --{row['command']}; docs/{row['doc']}):")
    for o in row["options"]:
        if o["file"] == "write":
            continue
        default = "None" if o["default"] is None else repr(o["default"])
        what = o["allowed"] + ("; " if o["allowed"] else "")
        if o["file"] in ("image", "data"):
            what = "an image (" + ("colour managed" if o["file"] == "image" else
                                   "its numbers") + "): an array, ImageBuf or file name; "
        elif o["file"] == "mesh":
            what = "a mesh file (OBJ or PLY); "
        lines.append(f"    {o['name']}={default}")
        lines.append(_wrap(what + o["help"], "        "))
    if row["subbands"]:
        lines.append("    subbands=False")
        lines.append(_wrap("True: also return the pyramid's subbands", "        "))
    lines.append("Every method also takes:")
    for name, default, what in _COMMON:
        lines.append(f"    {name}={default!r}")
        lines.append(_wrap(what, "        "))
    if row["example"]:
        lines += ["", "The same on the command line:", "    " + row["example"]]
    return "\n".join(lines)


def _make(row):
    command = row["command"]

    def method(*args, **kwargs):
        return _texsyn._run_method(command, args, kwargs)

    params = [_P(name, _P.POSITIONAL_ONLY, default=default)
              for name, default, _ in _INPUTS[row["inputs"]]]
    params += [_P(o["name"], _P.KEYWORD_ONLY, default=o["default"])
               for o in row["options"] if o["file"] != "write"]
    if row["subbands"]:
        params.append(_P("subbands", _P.KEYWORD_ONLY, default=False))
    params += [_P(name, _P.KEYWORD_ONLY, default=default) for name, default, _ in _COMMON]
    method.__signature__ = _inspect.Signature(params)
    method.__name__ = method.__qualname__ = row["name"]
    method.__module__ = __name__
    method.__doc__ = _doc(row)
    return method


method_names = tuple(row["name"] for row in _texsyn._method_table())
for _row in _texsyn._method_table():
    globals()[_row["name"]] = _make(_row)
del _row

__all__ = list(method_names) + ["Analysis", "Material", "Recipe", "Surface", "apply_map",
                                "method_names", "__version__"]
