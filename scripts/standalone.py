#!/usr/bin/env python3
"""Writes dist/wavepool-standalone.html: the demo page as one file that makes no network
request, so it opens by double-click from disk (file://) and inside <iframe sandbox="allow-scripts">.

Everything Trunk built goes inline: the page's stylesheet as a <style>, and one module script
holding the wasm module (gzip, then base 85 in an alphabet that needs no escaping in a JS
string or a <script>: 5 characters per 4 bytes instead of base64's 5⅓; the browser gunzips it
with DecompressionStream and instantiates it asynchronously), wasm-bindgen's JS (its exports turned into a closure's return
value), our own modules that embed.js imports, directly or through each other (each a closure
whose value holds its exports, after the modules it imports), embed.js (which sees WAVEPOOL_INLINE
and uses the inline wasm and a constructed stylesheet instead of the files next to it) and
index.html's own page script.

Usage: scripts/standalone.py DIST   (after `trunk build`; prints the file's size)
"""

import base64
import gzip
import json
import re
import sys
import urllib.parse
from pathlib import Path

# The single file must stay small enough to mail or upload to a learning platform.
BUDGET_BYTES = 1_600_000
# What the demo's JS takes from wasm-bindgen's module.
CORE_EXPORTS = ["WebDemo", "optionTable", "paramTable", "presetTable", "pageWords", "fresnelCurve", "panicForTests"]


# Base 85 digits: printable ASCII without the characters a JSON string or an inline <script>
# would escape or end on (" \\ < &), so the packed wasm is written as it is. embed.js decodes
# it with the same alphabet (it reads it from WAVEPOOL_INLINE.alphabet).
BASE85_ALPHABET = "".join(c for c in map(chr, range(0x21, 0x7F)) if c not in "\"\\<&'`$")[:85]


def base85(data):
    """4 bytes (big-endian, the last group zero-padded) as 5 digits, most significant first;
    the decoder knows the true length from the gzip stream's end."""
    digits = BASE85_ALPHABET
    data = data + b"\0" * (-len(data) % 4)
    out = []
    for i in range(0, len(data), 4):
        n = int.from_bytes(data[i : i + 4], "big")
        group = []
        for _ in range(5):
            n, d = divmod(n, 85)
            group.append(digits[d])
        out.append("".join(reversed(group)))
    return "".join(out)


def compact_js(js):
    """`js` without its lines' indentation and trailing spaces and without blank lines (a fifth
    of wasm-bindgen's module is indentation), which no JS statement depends on; lines inside a
    template literal, where they are the string's text, are kept as they are."""
    out, in_template = [], False
    for line in js.split("\n"):
        opens_or_closes = len(re.findall(r"(?<!\\)`", line)) % 2 == 1
        if in_template:
            out.append(line)
        elif opens_or_closes:
            out.append(line.lstrip())
        elif line.strip():
            out.append(line.strip())
        in_template ^= opens_or_closes
    if in_template:
        fail("a template literal opened and never closed: compact_js counts backticks per line (a lone one in a string or comment would mislead it)")
    return "\n".join(out)


def fail(message):
    sys.exit(f"standalone.py: {message}")


def core_as_closure(bindgen_js):
    """wasm-bindgen's ES module as an expression whose value holds its init and exports."""
    body, count = re.subn(r"^export (class|function|async function|const|let) ", r"\1 ", bindgen_js, flags=re.M)
    body, tail = re.subn(r"^export \{[^}]*\};?\s*$", "", body, flags=re.M)
    if count < len(CORE_EXPORTS) or tail != 1 or re.search(r"^export ", body, flags=re.M):
        fail("wasm-bindgen's output no longer has the shape this script expects (exports)")
    names = ", ".join(CORE_EXPORTS)
    return f"(() => {{\n{body}\nreturn {{ init: __wbg_init, {names} }};\n}})()"


IMPORT_LINE = re.compile(r'^import (?:(\w+)(?:, )?)?(?:\{ ([\w, ]+) \})? from "\./([\w-]+\.js)";\n', re.M)


def without_imports(js, name):
    """`js` with each import line turned into names taken from the module's closure (the core's
    from WAVEPOOL_CORE), and the modules it imports."""
    imported = []

    def take(match):
        default, names, module = match.groups()
        parts = ([f"init: {default}"] if default else []) + (names.split(", ") if names else [])
        if default and module != "wavepool.js":
            fail(f"{name} imports a default export from {module}; only wavepool.js has one")
        if module != "wavepool.js":
            imported.append(module)
        source = "WAVEPOOL_CORE" if module == "wavepool.js" else closure_name(module)
        return f"const {{ {', '.join(parts)} }} = {source};\n"

    return IMPORT_LINE.sub(take, js), imported


def closure_name(module):
    return "WAVEPOOL_" + re.sub(r"\W", "_", module[: -len(".js")]).upper()


def module_as_closure(js, name):
    """One of our ES modules as a closure returning its exports: `const WAVEPOOL_X = (() => ...)();`."""
    names = re.findall(r"^export (?:const|let|function|async function|class) (\w+)", js, flags=re.M)
    body = re.sub(r"^export ", "", js, flags=re.M)
    if not names or re.search(r"^(import|export) ", body, flags=re.M):
        fail(f"{name} no longer has the shape this script expects (exports, imports of ./x.js)")
    return f"const {closure_name(name)} = (() => {{\n{body}\nreturn {{ {', '.join(names)} }};\n}})();"


def own_modules_in_order(read, entry):
    """Our modules reachable from `entry`'s imports, each after those it imports, as closures;
    and `entry` itself with its imports taken from them."""
    done, closures = set(), []

    def visit(name, path):
        if name in path:
            fail(f"the modules import each other in a cycle: {' -> '.join([*path, name])}")
        if name in done:
            return
        js, imports = without_imports(read(name), name)
        for module in imports:
            visit(module, [*path, name])
        done.add(name)
        closures.append(module_as_closure(js, name))

    entry_js, imports = without_imports(read(entry), entry)
    for module in imports:
        visit(module, [entry])
    return closures, re.sub(r"^export ", "", entry_js, flags=re.M)


def main():
    if len(sys.argv) != 2:
        fail("usage: standalone.py DIST")
    dist = Path(sys.argv[1])
    read = lambda name: (dist / name).read_text(encoding="utf-8")
    wasm = (dist / "wavepool_bg.wasm").read_bytes()
    page = read("index.html")

    own_modules, embed = own_modules_in_order(read, "embed.js")
    if len(own_modules) < 3 or "WAVEPOOL_CORE" not in embed:
        fail("embed.js no longer imports the core and its own modules the way this script expects")

    # index.html: its page script (minus the import, mount is in the same module now), its
    # body, its title; the stylesheet and Trunk's script tags are replaced by inline ones.
    scripts = re.findall(r'<script type="module">(.*?)</script>', page, flags=re.S)
    page_script = next((s for s in scripts if "mount(" in s), None)
    if page_script is None:
        fail("index.html has no page script calling mount()")
    page_script = re.sub(r'^\s*import \{ [\w, ]+ \} from "\./embed\.js";\s*$', "", page_script, flags=re.M)
    body = re.search(r"<body>(.*?)<script", page, flags=re.S)
    title = re.search(r"<title>(.*?)</title>", page, flags=re.S)
    description = re.search(r'<meta name="description"[^>]*>', page)
    if not body or not title or not description:
        fail("index.html has no <body>, <title> or description where expected")
    icon = "data:image/svg+xml," + urllib.parse.quote(read("favicon.svg").strip())

    zipped = gzip.compress(wasm, compresslevel=9, mtime=0)
    packed = base85(zipped)
    picture = "data:image/webp;base64," + base64.b64encode((dist / "no-gpu.webp").read_bytes()).decode("ascii")
    # The catalogues but English's (which the core's tables hold) and the Fluent runtime.
    def packed_file(path):
        data = gzip.compress(path.read_bytes(), compresslevel=9, mtime=0)
        return [base85(data), len(data)]

    locales = {p.stem: packed_file(p) for p in sorted((dist / "locales").glob("*.ftl")) if p.stem != "en"}
    fluent = packed_file(dist / "locales" / "fluent-bundle.js")
    inline = "const WAVEPOOL_INLINE = " + json.dumps({"css": read("wavepool.css"), "wasm": packed, "wasmBytes": len(zipped), "alphabet": BASE85_ALPHABET, "picture": picture, "locales": locales, "fluent": fluent}) + ";"
    module = "\n".join(
        [
            inline,
            *map(compact_js, ["const WAVEPOOL_CORE = " + core_as_closure(read("wavepool.js")) + ";", *own_modules, embed, page_script]),
        ]
    ).replace("</script", "<\\/script")
    html = f"""<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <meta name="viewport" content="width=device-width, initial-scale=1">
  <title>{title.group(1)}</title>
  {description.group(0)}
  <link rel="icon" href="{icon}">
  <style>
{read("page.css")}
  </style>
</head>
<body>{body.group(1).rstrip()}
  <script type="module">
{module}
  </script>
</body>
</html>
"""
    out = dist / "wavepool-standalone.html"
    out.write_text(html, encoding="utf-8")
    size = out.stat().st_size
    print(f"    {out}: {size} bytes (wasm {len(wasm)} -> gzip {len(zipped)} -> {len(packed)} base 85; budget {BUDGET_BYTES})")
    if size > BUDGET_BYTES:
        fail(f"{out} is {size} bytes, over the {BUDGET_BYTES}-byte budget")


if __name__ == "__main__":
    main()
