#!/usr/bin/env python3
"""scripts/docs --check can fail: a copy of the README with one figure of a
fast block changed by 30 % is reported stale (exit 1), and the copy with the
figure restored passes; a copy that shows a picture no block makes fails. Usage: docs_test.py SOURCE_DIR BINARY SCRATCH"""
import os
import re
import shutil
import subprocess
import sys

source, binary, scratch = sys.argv[1:4]
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
readme = open(os.path.join(source, 'README.md')).read()
# The first fast block with a decimal figure; its last one (a figure, not a count).
name = None
for begin in re.finditer(r'<!-- coilsim:begin (\S+)[^\n]*\bfast\b[^\n]*-->\n', readme):
    end = readme.index(f'<!-- coilsim:end {begin.group(1)} -->', begin.end())
    figures = list(re.finditer(r'\d+\.\d+', readme[begin.end():end]))
    if figures:
        name, m = begin.group(1), figures[-1]
        break
if not name:
    sys.exit('README.md has no fast block with a decimal figure')
at = begin.end() + m.start()
stale = readme[:at] + repr(float(m.group()) * 1.3) + readme[at + len(m.group()):]


def check(text, only=True):
    path = os.path.join(scratch, 'README.md')
    open(path, 'w').write(text)
    select = ['--only', name] if only else ['--fast']
    return subprocess.run([sys.executable, os.path.join(source, 'scripts/docs'), '--check'] + select +
                          ['--binary', binary, path], capture_output=True, text=True)


r = check(stale)
print(r.stdout, r.stderr)
if r.returncode != 1 or 'is stale' not in r.stdout:
    sys.exit(f'a figure of {name} changed by 30 % was not reported stale')
r = check(readme)
print(r.stdout, r.stderr)
if r.returncode != 0:
    sys.exit(f'the README as it is should pass its own check of {name}')
# A picture made by hand (no block's command makes it) is refused by the check of the fast blocks.
r = check(readme + '\n![made by hand](docs/images/hand-made.png)\n', only=False)
print(r.stdout, r.stderr)
if r.returncode != 1 or 'docs/images/hand-made.png is made by no block' not in r.stdout:
    sys.exit('a picture that no block makes was not reported')
print(f'docs_test: block {name}: a 30 % change is caught, the README passes; a hand-made picture is caught')
