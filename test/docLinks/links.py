#!/usr/bin/env python3
"""The docs' links and length (test/docLinks).

    links.py [FILE...]

Checks every relative link, [text](path) and ![alt](path), in FILE (by
default every README.md and every docs/*.md of the repository): the path,
less any #anchor, must name a file or folder, relative to the file's own
folder.  Links with a scheme (https:, mailto:) and bare anchors (#x) are
not checked.  Prints one PASS: or FAIL: line per file, then, with no
FILE, the user pages' length: each of docs/*.md and README.md at most
300 lines, all together at most 1,500.  docs/design.md is written for
contributors, not users, and is not counted.  Exit status 0.
"""
import os
import re
import subprocess
import sys

LINK = re.compile(r'!?\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\)')
PAGE_MAX, TOTAL_MAX = 300, 1500


def broken(path):
    """The links of PATH that name nothing."""
    here = os.path.dirname(path)
    out = []
    inCode = False
    for n, line in enumerate(open(path, encoding='utf-8'), 1):
        if line.lstrip().startswith('```'):
            inCode = not inCode
            continue
        if inCode:
            continue
        for target in LINK.findall(line):
            if re.match(r'[a-zA-Z][a-zA-Z0-9+.-]*:', target) or \
                    target.startswith('#'):
                continue
            file = target.split('#')[0]
            if not os.path.exists(os.path.join(here, file)):
                out.append('line %d: %s' % (n, target))
    return out


def say(ok, what):
    print('%s: %s' % ('PASS' if ok else 'FAIL', what))


def main(files):
    default = not files
    if default:
        listed = subprocess.run(['git', 'ls-files', '*.md'],
                                capture_output=True, text=True).stdout
        files = sorted(f for f in listed.split()
                       if os.path.basename(f) == 'README.md'
                       or f.startswith('docs/'))
    for f in files:
        bad = broken(f)
        say(not bad, '%s: every relative link names a file%s'
            % (f, (' (broken: %s)' % ', '.join(bad)) if bad else ''))
    if default:
        pages = ['README.md'] + sorted(
            os.path.join('docs', f) for f in os.listdir('docs')
            if f.endswith('.md') and f != 'design.md')
        lengths = [(p, sum(1 for _ in open(p))) for p in pages]
        long = ['%s (%d)' % (p, n) for p, n in lengths if n > PAGE_MAX]
        say(not long, 'each user page (README.md, docs/*.md but design.md) at most %d '
            'lines%s' % (PAGE_MAX, (': ' + ', '.join(long)) if long else ''))
        total = sum(n for p, n in lengths)
        say(total <= TOTAL_MAX, 'the user pages together: %d lines, at most '
            '%d' % (total, TOTAL_MAX))


if __name__ == '__main__':
    main(sys.argv[1:])
