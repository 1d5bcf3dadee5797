"""Tokens of a pbrt-v4 scene file, for the scripts that read one outside illum (compare_peers.sh's
scene header, cycles_cornell.py's Cornell box): quoted strings (kept with their quotes), brackets and bare
words. Comments run from '#' to the end of the line; a '#' inside a quoted string is not a comment."""

import re

TOKEN_RE = re.compile(r'"[^"]*"|\[|\]|[^\s\[\]"]+')


def tokenize(text):
    tokens = []
    for line in text.splitlines():
        in_string = False
        for i, ch in enumerate(line):
            if ch == '"':
                in_string = not in_string
            elif ch == '#' and not in_string:
                line = line[:i]
                break
        tokens.extend(TOKEN_RE.findall(line))
    return tokens
