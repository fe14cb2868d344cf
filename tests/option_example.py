"""docs/extending.md's "An option" example, compiled into the library: each
block marked `<!-- not run: compiled into FILE by tests/option_example.py,
after "TEXT" -->` is inserted into a copy of FILE after the line holding
TEXT, and every patched source file is compiled (syntax only) with the
build's own flags (compile_commands.json) and the copies ahead of the source
tree on the include path.

usage: option_example.py SOURCE_DIR BUILD_DIR"""
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

MARKER = re.compile(r'<!-- not run: compiled into (\S+) by tests/option_example.py, after "(.*)" -->')


def blocks(markdown):
    lines = open(markdown).read().split("\n")
    for i, line in enumerate(lines):
        m = MARKER.match(line.strip())
        if not m:
            continue
        if not lines[i + 1].startswith("```"):
            sys.exit("%s:%d: the marker must stand right above a code block" % (markdown, i + 1))
        end = lines.index("```", i + 2)
        yield m.group(1), m.group(2), "\n".join(lines[i + 2:end])


def main():
    source, build = sys.argv[1], sys.argv[2]
    patched = {}
    for path, anchor, code in blocks(os.path.join(source, "docs", "extending.md")):
        text = patched.get(path) or open(os.path.join(source, path)).read()
        lines = text.split("\n")
        at = [i for i, line in enumerate(lines) if anchor in line]
        if len(at) != 1:
            sys.exit('%s: "%s" found %d times, must be once' % (path, anchor, len(at)))
        patched[path] = "\n".join(lines[:at[0] + 1] + [code] + lines[at[0] + 1:])
    if len(patched) < 3:
        sys.exit("expected blocks for three files, found %s" % sorted(patched))
    commands = {os.path.realpath(e["file"]): e for e in json.load(open(os.path.join(build, "compile_commands.json")))}
    with tempfile.TemporaryDirectory() as overlay:
        for path, text in patched.items():
            os.makedirs(os.path.dirname(os.path.join(overlay, path)), exist_ok=True)
            open(os.path.join(overlay, path), "w").write(text)
        compiled = 0
        for path in patched:
            entry = commands.get(os.path.realpath(os.path.join(source, path)))
            if not entry:
                continue  # a header
            args = shlex.split(entry["command"]) if "command" in entry else entry["arguments"]
            out = args.index("-o")
            args = args[:out] + args[out + 2:]
            args = [a for a in args if a != "-c" and not a.endswith(path)]
            args = args[:1] + ["-I" + overlay, "-fsyntax-only", os.path.join(overlay, path)] + args[1:]
            result = subprocess.run(args, cwd=entry["directory"], capture_output=True, text=True)
            if result.returncode != 0:
                sys.exit("%s with the example does not compile:\n%s" % (path, result.stderr[-4000:]))
            compiled += 1
        if compiled < 2:
            sys.exit("compiled %d patched sources; expected option_schema.cpp and options.cpp" % compiled)
    print("the option example compiles in %d patched sources" % compiled)


if __name__ == "__main__":
    main()
