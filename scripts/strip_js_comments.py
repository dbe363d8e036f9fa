#!/usr/bin/env python3
"""Cuts the comments out of the browser build's JavaScript (dist/*.js), line for line: a
comment's text goes, its line stays (empty), so an error's line number in the page is still the
source file's. The sources keep their comments; the download is budgeted (README).

Understands the JavaScript this project writes and wasm-bindgen generates: strings in '', ""
and `` (template literals, across lines, with ${...} holding code), // and /* */ comments, and
regular expressions where one can start (after an operator or an opening bracket)."""

import pathlib
import re
import sys

# After these (the last non-space character of code), or after these words, a "/" starts a
# regular expression.
REGEX_AFTER = set("(,=:[!&|?{};+-*%<>~^") | {""}
KEYWORD_BEFORE = re.compile(r"(?<![\w$.])(return|typeof|case|do|else|in|of|void|yield|await|throw)\s*$")


def strip(text: str) -> str:
    out = []
    i, n = 0, len(text)
    last = ""  # the last non-space code character
    stack = []  # open template literals (and the braces of their ${...}) we are inside
    while i < n:
        c = text[i]
        two = text[i : i + 2]
        if stack and stack[-1] == "`":
            # Inside a template literal: up to its end or a ${.
            if c == "\\":
                out.append(text[i : i + 2])
                i += 2
            elif c == "`":
                stack.pop()
                out.append(c)
                i += 1
                last = "`"
            elif two == "${":
                stack.append("{")
                out.append(two)
                i += 2
                last = "{"
            else:
                out.append(c)
                i += 1
            continue
        if two == "//":
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if two == "/*":
            j = text.find("*/", i + 2)
            end = n if j < 0 else j + 2
            # Its line breaks kept; on one line, a space (a/**/b is two tokens).
            out.append("\n" * text.count("\n", i, end) or " ")
            i = end
            continue
        if two in ("++", "--"):
            # x++ / 2 divides: the operator ends an operand.
            out.append(two)
            i += 2
            last = "a"
            continue
        if c in "'\"":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(text[i : j + 1])
            i = j + 1
            last = c
            continue
        if c == "`":
            stack.append("`")
            out.append(c)
            i += 1
            continue
        if c == "/" and (last in REGEX_AFTER or KEYWORD_BEFORE.search("".join(out[-12:]))):
            j, in_class = i + 1, False
            while j < n and (in_class or text[j] != "/") and text[j] != "\n":
                if text[j] == "\\":
                    j += 1
                elif text[j] == "[":
                    in_class = True
                elif text[j] == "]":
                    in_class = False
                j += 1
            out.append(text[i : j + 1])
            i = j + 1
            last = "/"
            continue
        if c == "{" and stack:
            stack.append("{")
        elif c == "}" and stack and stack[-1] == "{":
            stack.pop()
        out.append(c)
        if not c.isspace():
            last = c if not (c.isalnum() or c in "_$.)]") else "a"
        i += 1
    return "".join(out)


def main() -> None:
    folder = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "dist")
    for path in sorted(folder.glob("*.js")):
        text = path.read_text()
        slim = strip(text)
        assert slim.count("\n") == text.count("\n"), f"{path}: lines lost"
        path.write_text(slim)


if __name__ == "__main__":
    main()
