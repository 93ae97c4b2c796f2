#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""exported_symbols.py LIBTEXSYN SOURCE_DIR: libtexsyn exports its public API and nothing else.

Every defined dynamic symbol of the shared library (nm -D --defined-only, demangled) must
belong to namespace texsyn (functions, or the typeinfo and vtables of its classes; of
other libraries' templates only the weak instantiations of std:: templates over texsyn's
public types, which a demangled glob of core/texsyn.map cannot tell apart), and
every exported function's own name must appear in a public header (core/include/texsyn):
what only src/**/*_pvt.h declares is internal and stays hidden (the public headers'
visibility pragmas). Prints each offending symbol and exits 1 if there is any.
"""
import glob
import os
import re
import subprocess
import sys

# What the linker itself defines in every shared library.
LINKER = {"_init", "_fini", "__bss_start", "_edata", "_end"}
# The prefixes c++filt puts before a class's special symbols.
SPECIAL = re.compile(r"^(typeinfo for |typeinfo name for |vtable for |VTT for |"
                     r"construction vtable for |guard variable for )")


def exported(library):
    out = subprocess.run(["nm", "-DC", "--defined-only", library], check=True,
                         capture_output=True, text=True).stdout
    for line in out.splitlines():
        parts = line.split(None, 2)
        if len(parts) == 3:
            yield parts[1], parts[2]


def qualified_name(symbol):
    """The qualified name a symbol defines, without template arguments, ABI tags or a
    function's parameters and return type: 'texsyn::Q* std::copy<texsyn::Q>(...)' ->
    'std::copy', 'texsyn::f[abi:cxx11](int)' -> 'texsyn::f'."""
    symbol = symbol.replace("[abi:cxx11]", "")
    operator = symbol.find("::operator")
    if operator >= 0:
        return symbol[:operator] + "::operator"
    out, depth = [], 0
    for ch in symbol:
        if ch == "<":
            depth += 1
        elif ch == ">":
            depth -= 1
        elif depth == 0:
            if ch == "(":
                break
            out.append(ch)
    return "".join(out).split(" ")[-1]


def main():
    library, source = sys.argv[1], sys.argv[2]
    headers = "".join(open(p, encoding="utf-8").read()
                      for p in glob.glob(os.path.join(source, "core/include/texsyn/*.h*")))
    bad = []
    count = 0
    for kind, symbol in exported(library):
        count += 1
        if symbol in LINKER:
            continue
        plain = SPECIAL.sub("", symbol)
        name = qualified_name(plain)
        if kind in "Ww" and name.startswith("std::") and "texsyn::" in plain:
            continue  # a std:: template instantiated over public texsyn types (vague linkage)
        if not name.startswith("texsyn::"):
            bad.append(f"{kind} {symbol}: not in namespace texsyn")
            continue
        if plain != symbol or kind not in "TtWw":
            continue  # a class's typeinfo or vtable, or data: the class is public
        own = [part for part in name.split("::") if part and not part.startswith("{")]
        own = own[-1] if own else ""
        if own.startswith("operator") or own.startswith("~"):
            continue
        if not re.search(r"\b" + re.escape(own) + r"\b", headers):
            bad.append(f"{kind} {symbol}: '{own}' is declared in no public header")
    for b in bad:
        print(b)
    print(f"{count} exported symbols, {len(bad)} outside the public API")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
