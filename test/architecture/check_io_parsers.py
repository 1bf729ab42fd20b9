#!/usr/bin/env python3
"""Checks that the public headers of deformseg's io library include no file-format parser.

deformseg::io is compiled (src/io/): its public headers (include/deformseg/io.h and
include/deformseg/io/*.h, not io/internal/) declare what the library defines, so that a program
that reads files compiles none of tinygltf, Assimp, Draco, meshoptimizer or nlohmann-json. A
public header breaks the rule when it includes one of their headers, itself or through the
deformseg headers it includes (whatever #if surrounds the include). Run with the include/deformseg
folder; --self-test proves that the check catches a direct and an indirect include.
"""
import pathlib
import re
import sys

import header_checks

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
# The parsers' headers, as deformseg includes them.
PARSER = re.compile(r'^(tiny_gltf\.h|assimp/.*|draco/.*|meshoptimizer\.h|nlohmann/.*)$')


def public_headers(root):
    """The public io headers below `root` (include/deformseg), as paths relative to it."""
    headers = [path for path in sorted(root.glob('io/*.h'))]
    if (root / 'io.h').exists():
        headers.append(root / 'io.h')
    return [path.relative_to(root).as_posix() for path in headers]


def parser_chain(root, relative, seen):
    """The chain of includes from `relative` to a parser's header, or None."""
    if relative in seen:
        return None
    seen.add(relative)
    path = root / relative
    if not path.exists():  # a generated header (io/config.h) or one outside deformseg
        return None
    for included in INCLUDE.findall(path.read_text()):
        if PARSER.match(included):
            return [relative, included]
        if included.startswith('deformseg/'):
            chain = parser_chain(root, included[len('deformseg/'):], seen)
            if chain:
                return [relative] + chain
    return None


def problems(folder):
    root = pathlib.Path(folder)
    found = []
    for relative in public_headers(root):
        chain = parser_chain(root, relative, set())
        if chain:
            found.append(f'{relative}: includes a parser: {" -> ".join(chain)}')
    return found


def self_test():
    cases = {  # a tree of headers, and whether it breaks the rule
        'parser in a public header': ({'io/a.h': '#include <tiny_gltf.h>'}, True),
        'parser through another header': ({'io/a.h': '#include <deformseg/io/internal/b.h>',
                                            'io/internal/b.h': '#include <assimp/scene.h>'}, True),
        'parser under #if': ({'io/a.h': '#if X\n#include <nlohmann/json.hpp>\n#endif'}, True),
        'parser in the umbrella header': ({'io.h': '#include <draco/compression/decode.h>'}, True),
        'parser in a detail alone': ({'io/a.h': '#include <vector>', 'io/internal/b.h': '#include <meshoptimizer.h>'},
                                     False),
        'a declaration only': ({'io/a.h': 'namespace tinygltf {\nclass Model;\n}'}, False),
    }
    return header_checks.failed_cases(cases, problems)


if __name__ == '__main__':
    sys.exit(header_checks.main(sys.argv, problems, self_test))
