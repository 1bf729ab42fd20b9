#!/usr/bin/env python3
"""Checks the module rule of deformseg's headers (chapter "Architecture" of the manual).

The headers below include/deformseg/ form modules, one folder and one namespace each, in layers:
a module includes the foundation (the headers at the top: errors, threads), its own headers and
the public headers of the modules below it, never those above; a module's internal/ folder is
included by that module alone; a header of module M opens no namespace but deformseg::M and, for
its details, deformseg::M::internal; and no header includes itself through others (no circle,
which #pragma once would hide). Run with the include/deformseg folder; --self-test proves that
each rule catches what it should.
"""
import pathlib
import re
import sys

import header_checks

# Bottom to top, as the design draws them, with the colour type, which includes nothing, at the
# bottom (io's PLY writer colours faces): the mesh model; io, the formats; descriptors;
# segmentation; graphs; alignment; similarity; the search of motion collections; the store;
# evaluation. Each module may include those before it.
LAYERS = ['color', 'mesh', 'io', 'strain', 'signatures', 'temporal', 'spatiotemporal', 'ged', 'clustering',
          'alignment', 'similarity', 'search', 'store', 'evaluation']

INCLUDE = re.compile(r'^\s*#\s*include\s*<deformseg/([^>]+)>', re.M)
NAMESPACE = re.compile(r'^\s*namespace\s+([\w:]+)\s*\{', re.M)
# A namespace that only declares classes of another library (`namespace tinygltf { class Model; }`):
# what a header declares so as to name a parser's type without including the parser (io/gltf.h),
# which opens no namespace of that library's code.
FORWARD_DECLARATIONS = re.compile(r'^\s*namespace\s+\w+\s*\{\s*(?:(?:class|struct)\s+\w+\s*;\s*)+\}', re.M)


def module_of(relative):
    """The module of a header path below include/deformseg ('' for the foundation)."""
    parts = relative.split('/')
    return '' if len(parts) == 1 or parts[0] == 'internal' else parts[0]


def umbrella_module(relative):
    """The module a top-level umbrella header stands for, or None."""
    name = relative[:-2] if relative.endswith('.h') else relative
    return name if '/' not in relative and name in LAYERS else None


def include_problems(relative, included):
    mine, theirs = module_of(relative), module_of(included)
    umbrella = umbrella_module(relative)
    if umbrella:
        if theirs != umbrella or '/internal/' in included:
            return [f'the umbrella header of {umbrella} includes {included}']
        return []
    if theirs == '':
        if umbrella_module(included):
            return [f'includes the umbrella header {included}; include the headers it needs']
        return []
    if theirs not in LAYERS:
        return [f'includes {included} of an unknown module {theirs}']
    if theirs == mine:
        return []
    if '/internal/' in included:
        return [f'includes {included}, a detail of module {theirs}']
    if mine == '':
        return [f'the foundation includes {included} of module {theirs}']
    if LAYERS.index(theirs) > LAYERS.index(mine):
        return [f'module {mine} includes {included} of module {theirs}, which is above it']
    return []


def namespace_problems(relative, text):
    mine = module_of(relative)
    if umbrella_module(relative):
        return []
    nested_details = r'|internal(::\w+)*$'  # inside the module's own namespace
    allowed = re.compile((r'deformseg(::internal(::\w+)*)?$' if mine == '' else
                          rf'deformseg::{mine}(::internal(::\w+)*)?$') + nested_details)
    return [f'opens namespace {name}, not deformseg::{mine or "internal"}'
            for name in NAMESPACE.findall(FORWARD_DECLARATIONS.sub('', text)) if not allowed.match(name)]


def circle_problems(includes):
    """A circle of includes, as one problem naming its headers, found by depth-first search."""
    state = {}  # header -> 'open' while on the search's path, 'done' after

    def visit(header, path):
        state[header] = 'open'
        for included in includes.get(header, []):
            if state.get(included) == 'open':
                return path[path.index(included):] + [included]
            if included not in state:
                circle = visit(included, path + [included])
                if circle:
                    return circle
        state[header] = 'done'
        return None

    for header in sorted(includes):
        if header not in state:
            circle = visit(header, [header])
            if circle:
                return [f'{circle[0]}: includes itself through ' + ' -> '.join(circle[1:])]
    return []


def problems(root):
    root = pathlib.Path(root)
    found = []
    includes = {}
    for path in sorted(root.rglob('*.h')):
        relative = path.relative_to(root).as_posix()
        mine = module_of(relative)
        if mine and mine not in LAYERS:
            found.append(f'{relative}: module {mine} is in no layer')
            continue
        text = path.read_text()
        includes[relative] = INCLUDE.findall(text)
        for included in includes[relative]:
            found += [f'{relative}: {p}' for p in include_problems(relative, included)]
        found += [f'{relative}: {p}' for p in namespace_problems(relative, text)]
    return found + circle_problems(includes)


def self_test():
    cases = {  # a tree of one or two headers, and whether it breaks the rule
        'upward include': ({'strain/a.h': '#include <deformseg/similarity/b.h>', 'similarity/b.h': ''}, True),
        'downward include': ({'similarity/a.h': '#include <deformseg/strain/b.h>', 'strain/b.h': ''}, False),
        'detail of another module': ({'io/a.h': '#include <deformseg/strain/internal/b.h>',
                                      'strain/internal/b.h': ''}, True),
        'own detail': ({'strain/a.h': '#include <deformseg/strain/internal/b.h>', 'strain/internal/b.h': ''}, False),
        'foundation reaching up': ({'threads.h': '#include <deformseg/mesh/a.h>', 'mesh/a.h': ''}, True),
        'module in no layer': ({'extras/a.h': ''}, True),
        'namespace of another module': ({'strain/a.h': 'namespace deformseg::mesh {\n}'}, True),
        'plain deformseg namespace in a module': ({'strain/a.h': 'namespace deformseg {\n}'}, True),
        "another library's class declared": ({'io/a.h': 'namespace tinygltf {\nclass Model;\n}'}, False),
        "another library's namespace opened": ({'io/a.h': 'namespace tinygltf {\nclass Model;\nint f();\n}'}, True),
        'module namespace and its details': ({'strain/a.h': 'namespace deformseg::strain {\nnamespace internal {\n}\n}\n'
                                              'namespace deformseg::strain::internal {\n}'}, False),
        'umbrella of its module': ({'strain.h': '#include <deformseg/strain/a.h>', 'strain/a.h': ''}, False),
        'umbrella reaching elsewhere': ({'strain.h': '#include <deformseg/mesh/a.h>', 'mesh/a.h': ''}, True),
        'module including an umbrella': ({'similarity/a.h': '#include <deformseg/strain.h>', 'strain.h': ''}, True),
        'circle in a module': ({'strain/a.h': '#include <deformseg/strain/b.h>',
                                'strain/b.h': '#include <deformseg/strain/c.h>',
                                'strain/c.h': '#include <deformseg/strain/a.h>'}, True),
        'shared header, no circle': ({'strain/a.h': '#include <deformseg/strain/b.h>\n#include <deformseg/strain/c.h>',
                                      'strain/b.h': '#include <deformseg/strain/c.h>', 'strain/c.h': ''}, False),
        'io above the store': ({'io/a.h': '#include <deformseg/store/b.h>', 'store/b.h': ''}, True),
        'similarity reaching up to search': ({'similarity/a.h': '#include <deformseg/search/b.h>', 'search/b.h': ''},
                                             True),
        'the store above search': ({'store/a.h': '#include <deformseg/search/b.h>', 'search/b.h': ''}, False),
    }
    return header_checks.failed_cases(cases, problems)


if __name__ == '__main__':
    sys.exit(header_checks.main(sys.argv, problems, self_test))
