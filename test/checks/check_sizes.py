#!/usr/bin/python3
"""No source file longer than 450 lines, no function longer than 60.

usage: check_sizes.py [--junit RESULT.xml] REPO_ROOT

Every C++ file under src/ and include/ is measured. A function counts from
the line that opens its body (the line of the signature that ends with
`{`) to the line of its closing brace, lambdas and local classes inside it
included. Bodies of classes, structs, unions, enums and namespaces are not
functions: the functions defined in them are measured one by one. Braces in
comments, string and character literals and preprocessor lines do not
count. A file whose braces do not balance fails too, since its functions
cannot be measured.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from junit_result import write_junit  # noqa: E402

MAX_FILE_LINES = 450
MAX_FUNCTION_LINES = 60
TOPS = ("src", "include")
SUFFIXES = (".h", ".hh", ".hpp", ".hxx", ".inl", ".ipp", ".c", ".cc", ".cpp", ".cxx")

IDENTIFIER_TAIL = re.compile(r"[A-Za-z0-9_.']*$")
RAW_PREFIXES = {"R", "u8R", "uR", "UR", "LR"}
ACCESS = re.compile(r"^\s*(?:public|protected|private)\s*:(?!:)")
ATTRIBUTE = re.compile(r"^\s*\[\[.*?\]\]")
CLASS_HEAD = re.compile(
    r"^(?:class|struct|union|enum(?:\s+(?:class|struct))?)\b"  # the keyword
    r"(?:\s*\[\[.*?\]\])?(?:\s*alignas\s*\([^)]*\))?"          # attributes
    r"(?:\s*(?P<name>[A-Za-z_][\w:]*)(?:\s*<.*>)?)?"           # its name
    r"(?:\s+final)?(?:\s*:(?!:).*)?\s*$",                      # bases, underlying type
    re.S)
# What may follow a function's parameter list before its body.
AFTER_PARAMETERS = re.compile(
    r"^(?:\s*(?:const|volatile|noexcept(?:\s*\(.*\))?|override|final|mutable|try|&&?|->.*))*\s*$",
    re.S)
OPERATOR = re.compile(r"\boperator\s*(?:\(\s*\)|\[\s*\]|[^\s\w(]+)")
OPERATOR_NAME = re.compile(
    r"((?:[A-Za-z_]\w*\s*(?:<[^;{}]*?>)?\s*::\s*)*"
    r"operator\s*(?:\(\s*\)|\[\s*\]|[^\s\w(]+|\s+[\w:<>*& ]+?))\s*\(")
NAME_BEFORE = re.compile(r"((?:[A-Za-z_]\w*\s*(?:<[^;{}]*?>)?\s*::\s*)*~?[A-Za-z_]\w*)$")
CONTROL = {"if", "for", "while", "switch", "catch", "do", "else", "return", "sizeof"}


def blank(text):
    """`text` with every character but newlines made a space."""
    return re.sub(r"[^\n]", " ", text)


def strip_code(text):
    """`text` with comments, string and character literals and preprocessor
    lines blanked (newlines kept, so line numbers stay); a literal keeps its
    quotes."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        pair = text[i:i + 2]
        # The token a quote ends: a raw string's prefix, or a number's digits.
        before = IDENTIFIER_TAIL.search(text[max(0, i - 64):i]).group(0) if c in "\"'" else ""
        if pair == "//":
            end = text.find("\n", i)
            end = n if end < 0 else end
        elif pair == "/*":
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
        elif c == '"' and before in RAW_PREFIXES:  # R"delimiter( ... )delimiter"
            open_paren = text.find("(", i)
            closing = ")" + text[i + 1:open_paren] + '"'
            end = text.find(closing, open_paren)
            end = n if end < 0 else end + len(closing)
            out.append('"' + blank(text[i + 1:end - 1]) + '"')
            i = end
            continue
        elif c == '"' or (c == "'" and not before[:1].isdigit()):  # not 1'000
            j = i + 1
            while j < n and text[j] not in (c, "\n"):
                j += 2 if text[j] == "\\" else 1
            closed = j < n and text[j] == c
            out.append(c + blank(text[i + 1:j]) + (c if closed else ""))
            i = j + 1 if closed else j
            continue
        else:
            out.append(c)
            i += 1
            continue
        out.append(blank(text[i:end]))
        i = end
    lines = "".join(out).split("\n")
    continued = False
    for number, line in enumerate(lines):
        if continued or line.lstrip().startswith("#"):
            continued = line.rstrip().endswith("\\")
            lines[number] = " " * len(line)
    return "\n".join(lines)


def top_level(head, wanted):
    """Positions in `head` of the characters in `wanted` outside (), []
    and, outside those, <> (template arguments)."""
    brackets = angles = 0
    found = []
    for i, c in enumerate(head):
        if brackets == 0 and angles == 0 and c in wanted:
            found.append(i)
        if c in "([":
            brackets += 1
        elif c in ")]":
            brackets = max(0, brackets - 1)
        elif brackets:
            continue
        elif c == "<":
            angles += 1
        elif c == ">" and head[i - 1:i] != "-" and angles:
            angles -= 1
    return found


def closing_paren(head, start):
    """The position of the `)` that closes the `(` at `start`."""
    depth = 0
    for i in range(start, len(head)):
        depth += {"(": 1, ")": -1}.get(head[i], 0)
        if depth == 0:
            return i
    return len(head)


def strip_template(head):
    """`head` without its leading template parameter list(s)."""
    while True:
        match = re.match(r"\s*template\s*<", head)
        if not match:
            return head
        depth, i = 1, match.end()
        while i < len(head) and depth:
            depth += {"<": 1, ">": -1}.get(head[i], 0)
            i += 1
        head = head[i:]


def clean_head(head):
    """The declaration before a `{`, without access labels, attributes and
    template parameters, whitespace collapsed."""
    while True:
        stripped = ATTRIBUTE.sub("", ACCESS.sub("", strip_template(head)))
        if stripped == head:
            return " ".join(head.split())
        head = stripped


def classify(head):
    """What a `{` at namespace or class scope opens, from the declaration
    before it: ("scope", class name or None) for a namespace, class or the
    like, whose body holds declarations; ("function", name) for a
    function's body; ("other", None) for an initializer, or a member's in a
    constructor's initializer list."""
    head = clean_head(head)
    if re.match(r"(?:inline\s+)?namespace\b", head) or re.match(r'extern\s*"', head):
        return "scope", None
    class_head = CLASS_HEAD.match(head)
    if class_head:
        return "scope", class_head.group("name")
    plain = OPERATOR.sub("operator_", head)  # no brackets or `=` in operator names
    if top_level(plain, "="):
        return "other", None  # `x = {...}`, `f = [] {...}`
    opens = top_level(plain, "(")
    if not opens:
        return "other", None  # `Type value{...}`
    named = OPERATOR_NAME.search(head) or NAME_BEFORE.search(plain[:opens[0]].rstrip())
    name = named and " ".join(named.group(1).split()).replace(" ::", "::").replace(":: ", "::")
    if not name or name in CONTROL:
        return "other", None
    rest = plain[closing_paren(plain, opens[0]) + 1:]
    initializers = re.match(r"(?:\s*noexcept(?:\s*\(.*?\))?)?\s*:(?!:)", rest)
    if initializers:
        # Its body follows the last initializer; `member_{` opens one.
        return ("function", name) if rest.rstrip().endswith((")", "}")) else ("other", None)
    return ("function", name) if AFTER_PARAMETERS.match(rest) else ("other", None)


def functions_of(code):
    """(line of its `{`, lines, name) of every function in stripped `code`,
    and the line of a brace that does not balance (or None)."""
    functions = []
    stack = []  # (kind, name, line of its `{`): scopes, then at most a function or other
    head_start = 0  # where the declaration before the next `{` begins
    parens = 0
    line = 1
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
            continue
        if stack and stack[-1][0] != "scope":
            # In a function's body or an initializer: every brace nests.
            if c == "{":
                stack.append(("block", None, line))
            elif c == "}":
                kind, name, opened = stack.pop()
                if kind == "function":
                    functions.append((opened, line - opened + 1, name))
                    head_start = i + 1
                # An initializer's declaration goes on to its `;`.
            continue
        if c == "(":
            parens += 1
        elif c == ")":
            parens = max(0, parens - 1)
        elif c == ";" and parens == 0:
            head_start = i + 1
        elif c == "{":
            # In parentheses: an argument `f({...})` or a default `T x = {}`.
            kind, name = ("other", None) if parens else classify(code[head_start:i])
            if kind == "function":  # a member defined in its class: Class::member
                name = "::".join([scope for _, scope, _ in stack if scope] + [name])
            stack.append((kind, name, line))
            if kind == "scope":
                head_start = i + 1
        elif c == "}":
            if not stack:
                return functions, line
            stack.pop()
            head_start = i + 1
    return functions, (stack[-1][2] if stack else None)


def measure(root):
    """(long files, long functions): problem lines for each rule."""
    long_files, long_bodies = [], []
    for top in TOPS:
        for directory, subdirectories, files in os.walk(os.path.join(root, top)):
            subdirectories.sort()
            for name in sorted(files):
                if not name.endswith(SUFFIXES):
                    continue
                path = os.path.relpath(os.path.join(directory, name), root)
                with open(os.path.join(root, path), encoding="utf-8") as source:
                    text = source.read()
                lines = len(text.splitlines())
                if lines > MAX_FILE_LINES:
                    long_files.append(f"{path}:1: {lines} lines: the file "
                                      f"(at most {MAX_FILE_LINES})")
                functions, unbalanced = functions_of(strip_code(text))
                if unbalanced is not None:
                    long_bodies.append(f"{path}:{unbalanced}: braces do not balance: "
                                       "its functions cannot be measured")
                for line, length, function in functions:
                    if length > MAX_FUNCTION_LINES:
                        long_bodies.append(f"{path}:{line}: {length} lines: {function}")
    return long_files, long_bodies


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--junit", help="write a junit result here")
    parser.add_argument("root")
    args = parser.parse_args()
    long_files, long_bodies = measure(os.path.abspath(args.root))
    for problem in long_files + long_bodies:
        print(problem)
    if args.junit:
        write_junit(args.junit, "sizes",
                    [("file_length", long_files), ("function_length", long_bodies)])
    return 1 if long_files or long_bodies else 0


if __name__ == "__main__":
    sys.exit(main())
