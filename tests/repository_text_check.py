#!/usr/bin/env python3
"""Checks the repository's own words (standard library only).

  repository_text_check.py ROOT history   no file speaks of how the project was made
  repository_text_check.py ROOT paths     every link and repository path that the README,
                                          docs/ and the comments of host/, kernels/, tests/
                                          and tools/ name exists

history: a reader cannot check "the stop where X changed", a working session, a machine
that was borrowed or "the development machine"; a figure names its commit, date, machine
and command instead (docs/performance.md). Every tracked text file is read.

paths: Markdown links (the file, and the heading an #anchor or a quoted section names),
no path that leaves the repository ("../shared/..."), paths from the repository root (host/..., kernels/..., scenes/...; globs and {a,b} lists
expanded), paths relative to a source folder (closure/bsdf.cl in kernels/, common/parallel.h
in host/) and bare source file names (test_render.cpp) must name files that exist, or files
that git ignores (what a build or a study writes). Upper-case words are placeholders
(scenes/NAME.gltf) and are not looked up.

Prints one line per finding, FILE:LINE: what is wrong; exit status 1 if there is any.
"""
import fnmatch
import os
import re
import subprocess
import sys

# Spelled so that this file does not match itself.
HISTORY_PATTERNS = [
    (re.compile(r"\bstops?[ \t-]+\d+", re.I), "a numbered stop"),
    (re.compile(r"\bsess" r"ions?\b", re.I), "a working session"),
    (re.compile(r"\bdev(elopment)? mach" r"ine\b", re.I), "the development machine"),
    (re.compile(r"\ble" r"nt\b", re.I), "a borrowed machine"),
    (re.compile(r"\bspeed iss" r"ue\b", re.I), "the speed issue"),
    (re.compile(r"\bbranch,? not ke" r"pt\b", re.I), "a branch not kept"),
    (re.compile(r"\b(the )?iss" r"ue( \d+|'s)", re.I), "an issue of the tracker"),
]

BINARY_EXTENSIONS = {".png", ".jpg", ".jpeg", ".exr", ".hdr", ".glb", ".bin", ".ply", ".gz", ".xz"}
SOURCE_EXTENSIONS = {".cpp", ".h", ".cl", ".py", ".sh", ".cmake", ".md", ".txt", ".supp"}
ROOT_FOLDERS = ("host", "kernels", "tests", "tools", "docs", "scenes", ".ci")
# Names of other projects' files (Cycles', pbrt's, CMake's) that comments compare with, and
# words that look like paths.
NOT_OURS = {"bsdf.h", "closure/bsdf_sheen.h", "bxdfs.h", "kernel/data_arrays.h", "integrator/megakernel.h",
            "kernel/integrator/state_template.h",
            "OpenImageIOConfig.cmake", "host/device"}
PLACEHOLDER = re.compile(r"(?<![A-Za-z])[A-Z]{2,}(?![a-z])")


def repository_files(root):
    """Tracked files and new files git does not ignore; every file but build trees without git."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                             check=True, capture_output=True).stdout
        files = [f for f in out.decode().split("\0") if f]
        return sorted(f for f in files if os.path.isfile(os.path.join(root, f)))
    except (OSError, subprocess.CalledProcessError):
        files = []
        for top, dirs, names in os.walk(root):
            rel = os.path.relpath(top, root)
            dirs[:] = [d for d in dirs if not (rel == "." and (d.startswith("build") or d == ".git"))]
            files += [os.path.normpath(os.path.join(rel, n)) for n in names]
        return sorted(files)


def read_text(root, rel):
    if os.path.splitext(rel)[1].lower() in BINARY_EXTENSIONS:
        return None
    with open(os.path.join(root, rel), "rb") as f:
        data = f.read()
    if b"\0" in data[:8192]:
        return None
    return data.decode("utf-8", errors="replace")


def check_history(root, files, this_file):
    findings = []
    for rel in files:
        if rel == this_file:
            continue
        text = read_text(root, rel)
        if text is None:
            continue
        for number, line in enumerate(text.splitlines(), 1):
            for pattern, what in HISTORY_PATTERNS:
                m = pattern.search(line)
                if m:
                    findings.append(f"{rel}:{number}: names {what} (\"{m.group(0)}\"): say what a reader can check")
    return findings


def comment_lines(rel, text):
    """(line number, text) of the comments of a source file; every line of a Markdown file."""
    ext = os.path.splitext(rel)[1]
    lines = text.splitlines()
    if ext == ".md":
        return list(enumerate(lines, 1))
    out = []
    if ext in (".cpp", ".h", ".cl", ".c"):
        in_block = False
        for number, line in enumerate(lines, 1):
            rest = line
            while rest:
                if in_block:
                    end = rest.find("*/")
                    out.append((number, rest if end < 0 else rest[:end]))
                    if end < 0:
                        break
                    in_block, rest = False, rest[end + 2:]
                    continue
                code = re.sub(r'"(\\.|[^"\\])*"', '""', rest)  # string literals are code
                slash, star = code.find("//"), code.find("/*")
                if slash >= 0 and (star < 0 or slash < star):
                    out.append((number, code[slash + 2:]))
                    break
                if star < 0:
                    break
                in_block, rest = True, code[star + 2:]
        return out
    # Scripts and CMake: '#' comments; Python docstrings count as comments too.
    in_doc = False
    for number, line in enumerate(lines, 1):
        if ext == ".py" and line.count('"""') % 2 == 1:
            out.append((number, line))
            in_doc = not in_doc
            continue
        if in_doc or (ext == ".py" and '"""' in line):
            out.append((number, line))
            continue
        m = re.search(r"(^|\s)#(?!!)(.*)", line)
        if m:
            out.append((number, m.group(2)))
    return out


def expand_braces(path):
    m = re.search(r"\{([^{}]*)\}", path)
    if not m:
        return [path]
    return [p for alt in m.group(1).split(",") for p in expand_braces(path[:m.start()] + alt + path[m.end():])]


def github_anchor(heading):
    text = re.sub(r"[`*_]|\[([^\]]*)\]\([^)]*\)", r"\1", heading.strip()).lower()
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


class Tree:
    def __init__(self, root, files):
        self.root, self.files = root, set(files)
        self.dirs = {os.path.dirname(f) for f in files}
        for d in list(self.dirs):
            while d:
                d = os.path.dirname(d)
                self.dirs.add(d)
        self.basenames = {os.path.basename(f) for f in files}
        self._anchors = {}
        self._ignored = {}

    def ignored(self, rel):
        """Whether git ignores rel: an output of the build or of a study, not a source file."""
        if rel not in self._ignored:
            try:
                self._ignored[rel] = subprocess.run(["git", "-C", self.root, "check-ignore", "-q", "--no-index", rel],
                                                    capture_output=True).returncode == 0
            except OSError:
                self._ignored[rel] = False
        return self._ignored[rel]

    def exists(self, rel):
        rel = os.path.normpath(rel).rstrip("/")
        if any(c in rel for c in "*?["):
            return any(fnmatch.fnmatch(f, rel) for f in self.files)
        return rel in self.files or rel in self.dirs

    def anchors(self, rel):
        if rel not in self._anchors:
            seen, anchors, fence = {}, set(), False
            for line in (read_text(self.root, rel) or "").splitlines():
                if line.startswith("```"):
                    fence = not fence
                m = None if fence else re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
                if m:
                    a = github_anchor(m.group(1))
                    n = seen.get(a, 0)
                    seen[a] = n + 1
                    anchors.add(a if n == 0 else f"{a}-{n}")
            self._anchors[rel] = anchors
        return self._anchors[rel]

    def headings(self, rel):
        return {github_anchor(h) for h in self.anchors(rel)} | self.anchors(rel)


ROOT_PATH = re.compile(r"(?<![\w./~$-])((?:" + "|".join(re.escape(d) for d in ROOT_FOLDERS) +
                       r")/[\w./*{},<>-]*)")
RELATIVE_PATH = re.compile(r"(?<![\w./~$-])((?:[a-z_][\w-]*/)+[\w-]+\.(?:cpp|h|cl|py|sh|cmake))\b")
BARE_NAME = re.compile(r"(?<![\w./~$-])([A-Za-z_][\w-]*\.(?:cpp|h|cl|py|sh|cmake|md))\b(?![/\w])")
UP_PATH = re.compile(r"(?<![\w.\"'])((?:\.\./)+[\w./-]*\w)")  # a quoted one is an example
MD_LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
SECTION_REF = re.compile(r"((?:[\w./-]+/)?[\w-]+\.md|README)\b(?:,|:)?\s+(?:section\s+)?\"([^\"]+)\"")


def check_paths(root, files):
    tree = Tree(root, files)
    findings = []
    checked = [f for f in files
               if f == "README.md" or f.endswith(".md") and f.startswith("docs/")
               or f.split("/")[0] in ("host", "kernels", "tests", "tools") or f in ("CMakeLists.txt", ".ci/run")]
    for rel in checked:
        if rel.startswith("tests/corpus/files/") or rel.startswith("tests/references/"):
            continue
        text = read_text(root, rel)
        if text is None:
            continue
        here = os.path.dirname(rel)
        top = rel.split("/")[0]
        fence = False
        for number, line in comment_lines(rel, text):
            if rel.endswith(".md") and line.startswith("```"):
                fence = not fence
            where = f"{rel}:{number}"
            if rel.endswith(".md"):
                for m in MD_LINK.finditer(line):
                    target = m.group(1)
                    if re.match(r"[a-z]+:", target):
                        continue
                    path, _, anchor = target.partition("#")
                    file = os.path.normpath(os.path.join(here, path)) if path else rel
                    if path and not tree.exists(file):
                        findings.append(f"{where}: link to {target}: no such file in the repository")
                    elif anchor and file.endswith(".md") and anchor not in tree.anchors(file):
                        findings.append(f"{where}: link to {target}: {file} has no heading with that anchor")
            for m in SECTION_REF.finditer(line):
                doc, section = m.group(1), m.group(2)
                file = "README.md" if doc in ("README", "README.md") else doc
                if not tree.exists(file):
                    file = os.path.normpath(os.path.join(here, doc))
                if tree.exists(file) and github_anchor(section) not in tree.anchors(file):
                    findings.append(f"{where}: {doc} has no section \"{section}\"")
            for m in ROOT_PATH.finditer(line):
                path = m.group(1).rstrip(".,:;)")
                if "<" in path or ">" in path or PLACEHOLDER.search(path) or path in NOT_OURS:
                    continue
                if not all(tree.exists(p) or tree.ignored(p) for p in expand_braces(path)):
                    findings.append(f"{where}: {path}: no such file or folder in the repository")
            for m in UP_PATH.finditer(line):
                path = os.path.normpath(os.path.join(here, m.group(1)))
                if path.startswith(".."):
                    findings.append(f"{where}: {m.group(1)}: points outside the repository")
                elif not tree.exists(path):
                    findings.append(f"{where}: {m.group(1)}: no such file or folder in the repository")
            if fence:
                continue
            for m in RELATIVE_PATH.finditer(line):
                path = m.group(1)
                if path.split("/")[0] in ROOT_FOLDERS or path.split("/")[0].startswith("build") or \
                        path in NOT_OURS or PLACEHOLDER.search(path):
                    continue
                bases = [here, top, "host", "kernels", "tests", "tools", ""]
                if not any(tree.exists(os.path.join(b, path)) for b in bases):
                    findings.append(f"{where}: {path}: no such file under {here or '.'}, host/, kernels/, "
                                    "tests/ or tools/")
            for m in BARE_NAME.finditer(line):
                name = m.group(1)
                if len(name.split(".")[0]) < 3 or PLACEHOLDER.search(name) and not name.endswith(".md"):
                    continue  # wo.h is a dot product in a formula; OUT.cpp a placeholder, README.md not
                if name not in tree.basenames and name not in NOT_OURS:
                    findings.append(f"{where}: {name}: no file of that name in the repository")
    arch = "docs/architecture.md"
    if arch in tree.files:
        text = read_text(root, arch)
        for top in ("host", "kernels"):
            entries = {f.split("/")[1] + ("/" if f.count("/") > 1 else "") for f in files if f.startswith(top + "/")}
            findings += [f"{arch}: {top}/{e} is not in the map of the tree" for e in sorted(entries)
                         if f"{top}/{e}" not in text]
    return findings


def main():
    if len(sys.argv) != 3 or sys.argv[2] not in ("history", "paths"):
        sys.exit(__doc__)
    root = os.path.abspath(sys.argv[1])
    files = repository_files(root)
    this_file = os.path.relpath(os.path.abspath(__file__), root)
    findings = check_history(root, files, this_file) if sys.argv[2] == "history" else check_paths(root, files)
    for f in findings:
        print(f)
    print(f"{sys.argv[2]}: {len(files)} files, {len(findings)} findings")
    sys.exit(1 if findings else 0)


if __name__ == "__main__":
    main()
