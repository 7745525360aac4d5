#!/usr/bin/python3
"""The documents and the comments that cite them agree with the repository.

usage: check_docs.py [--junit RESULT.xml] [--list] REPO_ROOT

Three testcases, each failing with one `path:line: message` per problem:

  markdown_links  every relative link of README.md and docs/*.md (`[text](path)`,
                  `![alt](path)`, `[name]: path`) names a file or folder that
                  exists, and its `#anchor`, if any, is a heading of the target
                  (GitHub's anchors: lower case, punctuation but - and _
                  dropped, spaces to -, a repeated heading gets -1, -2, ...)
  citations       a Markdown file named in a comment of the sources, or in the
                  text of the documents, exists (path from the repository
                  root, or from the citing file's folder), and a citation
                  `docs/design.md, "Layers"` (the path, a comma, the title of
                  a heading in double quotes) names a heading of that file,
                  written as the heading is written (backticks aside)
  references      no comment or document names a section by number rather
                  than by title, an issue or pull request by its number (a
                  public upstream one, owner/repo#123, is fine), or a path
                  out of the repository into the shared folder beside it

The sources are every file under src/, include/, test/, scripts/, launch/,
config/, msg/ and srv/, CMakeLists.txt, Makefile, package.xml and bench/*.py;
their comments are what the file type says they are (// and /* */ in C++,
# in Python, shell, CMake, YAML and the ROS message files, <!-- --> in XML,
and Python's docstrings). Consecutive comment lines are read as one text, so
a citation may wrap. docs/testing.md, "Docs check" says how to cite.
"""
import argparse
import glob
import os
import re
import sys
import urllib.parse

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from junit_result import write_junit  # noqa: E402

DOCUMENTS = ["README.md", "docs/*.md"]
SOURCE_TREES = ["src", "include", "test", "scripts", "launch", "config", "msg", "srv"]
SOURCE_FILES = ["CMakeLists.txt", "Makefile", "package.xml", "bench/*.py"]

C_LIKE = (".h", ".hpp", ".hh", ".c", ".cc", ".cpp", ".cxx")
HASH_LIKE = (".py", ".sh", ".bash", ".cmake", ".yaml", ".yml", ".rviz", ".msg", ".srv",
             ".action", ".supp", ".txt", ".cfg")
XML_LIKE = (".launch", ".test", ".xml", ".urdf", ".xacro")

# A Markdown file named in text: a path of word characters, dots and dashes
# whose last part starts with a letter or digit (not `_targets.md`, a suffix)
# and is not part of a glob or placeholder (`*_motion.md`, `<plan>.md`).
MD_PATH = re.compile(r"(?<![\w./*<>{}$-])((?:\.\./|\./)*(?:[\w.-]+/)*[A-Za-z0-9][\w.-]*\.md)\b")
# What may follow it: a section title in double quotes, or a number.
TITLE_AFTER = re.compile(r'[`\]]*\s*,\s*"([^"]+)"')
NUMBER_AFTER = re.compile(r"[`\])]*\s*(?:'s\s+)?(?:sections?|§)\s*\d", re.IGNORECASE)
# README cited without its extension, as a citation or by a section number.
README_BARE = re.compile(r"\bREADME\b(?!\.md)(?=[`\]]*\s*(?:,\s*\"|(?:'s\s+)?(?:sections?|§)\s*\d))")
SECTION_SIGN = re.compile(r"§\s*\d")
ISSUE_WORD = re.compile(r"\b(?:[Ii]ssues?|[Tt]ickets?|PRs?|[Pp]ull requests?)\s*#?\s*\d+\b")
HASH_NUMBER = re.compile(r"#\d+\b")
UPSTREAM = re.compile(r"[A-Za-z0-9][\w.-]*/[\w.-]+$")
SHARED = re.compile(r"\.\./shared\b")
URL = re.compile(r"\b[a-z][a-z0-9+.-]*://\S+")


# --- reading ------------------------------------------------------------------


def read_lines(path):
    try:
        with open(path, encoding="utf-8") as text:
            return text.read().splitlines()
    except (UnicodeDecodeError, OSError):
        return None


def markdown_prose(lines):
    """(line number, text) of the lines of a Markdown file outside fenced
    code blocks."""
    fence = None
    for number, line in enumerate(lines, 1):
        stripped = line.lstrip()
        marker = re.match(r"(`{3,}|~{3,})", stripped)
        if marker:
            if fence is None:
                fence = marker.group(1)[0] * 3
            elif stripped.startswith(fence):
                fence = None
            continue
        if fence is None:
            yield number, line


def heading_texts(lines):
    """The text of each ATX heading (`## Title`) outside code blocks."""
    for _, line in markdown_prose(lines):
        match = re.match(r"\s{0,3}#{1,6}\s+(.*?)\s*#*\s*$", line)
        if match:
            yield match.group(1)


def plain(heading):
    """A heading as its rendered text: links to their text, no backticks or
    emphasis markers, spaces collapsed."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)
    text = text.replace("`", "")
    text = re.sub(r"(\*\*|\*)", "", text)
    return " ".join(text.split())


def slug(heading):
    """GitHub's anchor of a heading."""
    text = plain(heading).lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(lines):
    found = set()
    counts = {}
    for heading in heading_texts(lines):
        base = slug(heading)
        count = counts.get(base, 0)
        counts[base] = count + 1
        found.add(base if count == 0 else f"{base}-{count}")
    for _, line in markdown_prose(lines):
        for match in re.finditer(r'<a\s+(?:name|id)="([^"]+)"', line):
            found.add(match.group(1))
    return found


def titles(lines):
    return {plain(heading) for heading in heading_texts(lines)}


def c_comments(lines):
    """(line number, text) of each line's comment in C or C++."""
    in_block = False
    for number, line in enumerate(lines, 1):
        text, i, quote = [], 0, None
        while i < len(line):
            if in_block:
                end = line.find("*/", i)
                text.append(line[i:] if end < 0 else line[i:end])
                if end < 0:
                    i = len(line)
                else:
                    in_block, i = False, end + 2
                continue
            char = line[i]
            if quote:
                if char == "\\":
                    i += 2
                    continue
                if char == quote:
                    quote = None
            elif char in "\"'":
                quote = char
            elif line.startswith("//", i):
                text.append(line[i + 2:])
                break
            elif line.startswith("/*", i):
                in_block, i = True, i + 2
                continue
            i += 1
        if text:
            yield number, " ".join(text)


def hash_comments(lines, docstrings):
    """(line number, text) of each line's `#` comment (a `#` at the start or
    after white space, outside quotes), and of Python docstrings."""
    in_doc = None
    for number, line in enumerate(lines, 1):
        if in_doc:
            end = line.find(in_doc)
            yield number, line if end < 0 else line[:end]
            if end >= 0:
                in_doc = None
            continue
        if docstrings:
            match = re.match(r'\s*[rRbBuU]?("""|\'\'\')', line)
            if match:
                rest = line[match.end():]
                end = rest.find(match.group(1))
                yield number, rest if end < 0 else rest[:end]
                if end < 0:
                    in_doc = match.group(1)
                continue
        quote = None
        for i, char in enumerate(line):
            if quote:
                if char == quote:
                    quote = None
            elif char in "\"'":
                quote = char
            elif char == "#" and (i == 0 or line[i - 1].isspace()):
                yield number, line[i + 1:]
                break


def xml_comments(lines):
    in_comment = False
    for number, line in enumerate(lines, 1):
        text, i = [], 0
        while i < len(line):
            if in_comment:
                end = line.find("-->", i)
                text.append(line[i:] if end < 0 else line[i:end])
                if end < 0:
                    break
                in_comment, i = False, end + 3
            else:
                start = line.find("<!--", i)
                if start < 0:
                    break
                in_comment, i = True, start + 4
        if text:
            yield number, " ".join(text)


def comments(path, lines):
    name = os.path.basename(path)
    if name.endswith(C_LIKE):
        return list(c_comments(lines))
    if name.endswith(XML_LIKE):
        return list(xml_comments(lines))
    if name.endswith(HASH_LIKE) or name in ("CMakeLists.txt", "Makefile") or (
            lines and lines[0].startswith("#!")):
        return list(hash_comments(lines, name.endswith(".py")))
    return []


def blocks(numbered):
    """Runs of consecutive lines joined into one text each: (text, offsets)
    where offsets[i] is (start of line i in text, its line number)."""
    run = []
    for number, text in numbered:
        if run and number != run[-1][0] + 1:
            yield join(run)
            run = []
        run.append((number, text))
    if run:
        yield join(run)


def join(run):
    parts, offsets, at = [], [], 0
    for number, text in run:
        # Comment decoration: the rest of ///, //!, ///<, /** and * lines.
        text = re.sub(r"^[/!<*]+(?=\s|$)", "", text.strip()).strip()
        offsets.append((at, number))
        parts.append(text)
        at += len(text) + 1
    return " ".join(parts), offsets


def line_at(offsets, position):
    number = offsets[0][1]
    for start, line in offsets:
        if start > position:
            break
        number = line
    return number


# --- the checks -----------------------------------------------------------------


def resolve(root, citing, name):
    """The repository path of a file named in `citing`, or None."""
    for base in (root, os.path.dirname(os.path.join(root, citing))):
        candidate = os.path.normpath(os.path.join(base, name))
        if os.path.exists(candidate) and candidate.startswith(root):
            return os.path.relpath(candidate, root)
    return None


class Checker:
    def __init__(self, root):
        self.root = root
        self.problems = {"markdown_links": [], "citations": [], "references": []}
        self._lines = {}

    def lines_of(self, relative):
        if relative not in self._lines:
            self._lines[relative] = read_lines(os.path.join(self.root, relative)) or []
        return self._lines[relative]

    def report(self, case, path, line, message):
        self.problems[case].append(f"{path}:{line}: {message}")

    def check_text(self, path, text, offsets):
        """Citations and references in one run of comment or document text."""
        text = URL.sub(lambda m: " " * len(m.group(0)), text)
        for match in MD_PATH.finditer(text):
            line = line_at(offsets, match.start())
            name = match.group(1)
            if NUMBER_AFTER.match(text, match.end()):
                self.report("references", path, line,
                            f"{name} is cited by a section number: cite the section by its "
                            f"title, as {name}, \"<heading>\"")
            target = resolve(self.root, path, name)
            if target is None:
                # A link's text (`[name.md](path)`) is no path: the link is checked.
                if not text.startswith("]", match.end()):
                    self.report("citations", path, line,
                                f"names {name}, which is not in the repository")
                continue
            title = TITLE_AFTER.match(text, match.end())
            if title and target.endswith(".md"):
                wanted = " ".join(title.group(1).replace("`", "").split())
                if wanted not in titles(self.lines_of(target)):
                    self.report("citations", path, line,
                                f'cites "{title.group(1)}" of {name}, which has no such '
                                "heading")
        for match in README_BARE.finditer(text):
            self.report("citations", path, line_at(offsets, match.start()),
                        "cites README without its path: write README.md, \"<heading>\"")
        for match in SECTION_SIGN.finditer(text):
            self.report("references", path, line_at(offsets, match.start()),
                        "cites a section by number (§): cite a document and its heading")
        named = []
        for match in ISSUE_WORD.finditer(text):
            named.append(match.span())
            self.report("references", path, line_at(offsets, match.start()),
                        f"'{match.group(0)}' names an issue by number: say what it means")
        for match in HASH_NUMBER.finditer(text):
            inside = any(start <= match.start() < end for start, end in named)
            if not inside and not UPSTREAM.search(text[:match.start()]):
                self.report("references", path, line_at(offsets, match.start()),
                            f"'{match.group(0)}' names an issue by number: say what it means "
                            "(an upstream one as owner/repo#123)")
        for match in SHARED.finditer(text):
            self.report("references", path, line_at(offsets, match.start()),
                        "points into ../shared: the package stands alone")

    def check_links(self, path, lines):
        for number, line in markdown_prose(lines):
            code_free = re.sub(r"`[^`]*`", lambda m: " " * len(m.group(0)), line)
            targets = [m.group(1) for m in re.finditer(
                r"\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)", code_free)]
            definition = re.match(r"\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s|$)", code_free)
            if definition:
                targets.append(definition.group(1))
            for target in targets:
                self.check_link(path, number, target)

    def check_link(self, path, number, target):
        if not target or re.match(r"[a-zA-Z][a-zA-Z0-9+.-]*:", target) or \
                target.startswith("//"):
            return
        file_part, _, anchor = target.partition("#")
        file_part = urllib.parse.unquote(file_part)
        if file_part:
            if os.path.isabs(file_part):
                self.report("markdown_links", path, number,
                            f"link {target}: an absolute path; link relative to {path}")
                return
            full = os.path.normpath(os.path.join(self.root, os.path.dirname(path), file_part))
            if not os.path.exists(full):
                self.report("markdown_links", path, number,
                            f"link {target}: {file_part} does not exist")
                return
            relative = os.path.relpath(full, self.root)
        else:
            relative = path
        if anchor and relative.endswith(".md") and \
                anchor not in anchors(self.lines_of(relative)):
            self.report("markdown_links", path, number,
                        f"link {target}: {relative} has no heading with the anchor #{anchor}")

    def documents(self):
        found = []
        for pattern in DOCUMENTS:
            found += sorted(glob.glob(os.path.join(self.root, pattern)))
        return [os.path.relpath(path, self.root) for path in found]

    def sources(self):
        found = []
        for tree in SOURCE_TREES:
            for directory, folders, files in os.walk(os.path.join(self.root, tree)):
                folders[:] = sorted(f for f in folders if not f.startswith("."))
                found += [os.path.join(directory, name) for name in sorted(files)]
        for pattern in SOURCE_FILES:
            found += sorted(glob.glob(os.path.join(self.root, pattern)))
        return [os.path.relpath(path, self.root) for path in found if os.path.isfile(path)]

    def run(self):
        for path in self.documents():
            lines = self.lines_of(path)
            self.check_links(path, lines)
            prose = []
            for number, line in markdown_prose(lines):
                # Link targets are checked as links; the rest is text.
                prose.append((number, re.sub(r"\]\([^)]*\)", "]", line)))
            for text, offsets in blocks(prose):
                self.check_text(path, text, offsets)
        for path in self.sources():
            lines = read_lines(os.path.join(self.root, path))
            if lines is None:
                continue
            for text, offsets in blocks(comments(path, lines)):
                self.check_text(path, text, offsets)
        return self.problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--junit", help="write a junit result here")
    parser.add_argument("--list", action="store_true",
                        help="print every problem as path:line: message")
    parser.add_argument("root")
    args = parser.parse_args()
    problems = Checker(os.path.abspath(args.root)).run()
    if args.list:
        def where(problem):
            path, line, _ = problem.split(":", 2)
            return path, int(line)
        for problem in sorted((p for found in problems.values() for p in found), key=where):
            print(problem)
    for case, found in problems.items():
        if not args.list:
            print(f"{case}: " + (f"{len(found)} problems, the first {found[0]}" if found
                                 else "none"))
    if args.junit:
        write_junit(args.junit, "docs", list(problems.items()))
    return 1 if any(problems.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
