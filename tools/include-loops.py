#!/usr/bin/python3
"""Prints the loops in the include graph between the plugin's classes and exits 1 if any.

A class's files (vtkLightShaftX.h, vtkLightShaftX.cxx, and the pass's and others' split files,
vtkLightShaftXSomething.cxx/.h named in UNITS below) are one unit: they may include each other.

    tools/include-loops.py [folder ...]      (default: plugin)
"""
import os
import re
import sys
from collections import defaultdict

# Files of one class that do not share its base name.
UNITS = {
    "vtkLightShaftPassReadouts.cxx": "vtkLightShaftPass",
    "vtkLightShaftPassSampling.cxx": "vtkLightShaftPass",
    "vtkLightShaftPassInternals.h": "vtkLightShaftPass",
    "vtkLightShaftMediumInternals.h": "vtkLightShaftMedium",
    "vtkLightShaftErrorModelTable.h": "vtkLightShaftErrorModel",
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def unit_of(name):
    return UNITS.get(name, os.path.splitext(name)[0])


def graph(folders):
    files = {}
    for folder in folders:
        for directory, _, names in os.walk(folder):
            for name in names:
                if name.endswith((".h", ".cxx")):
                    files[name] = os.path.join(directory, name)
    edges = defaultdict(set)
    for name, path in files.items():
        with open(path, encoding="utf-8") as source:
            for included in INCLUDE.findall(source.read()):
                included = os.path.basename(included)
                if included in files and unit_of(included) != unit_of(name):
                    edges[unit_of(name)].add(unit_of(included))
    return edges


def strongly_connected(edges):
    """Tarjan's components of more than one unit."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []
    nodes = sorted(set(edges) | {b for targets in edges.values() for b in targets})

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    sys.setrecursionlimit(10000)
    for v in nodes:
        if v not in index:
            visit(v)
    return found


def shortest_cycle(edges, component):
    """A shortest loop through the component's first unit (breadth first)."""
    members = set(component)
    start = component[0]
    parents = {start: None}
    queue = [start]
    while queue:
        v = queue.pop(0)
        for w in sorted(edges.get(v, ())):
            if w == start:
                path = [v]
                while parents[path[-1]] is not None:
                    path.append(parents[path[-1]])
                return list(reversed(path)) + [start]
            if w in members and w not in parents:
                parents[w] = v
                queue.append(w)
    return component


def main():
    folders = sys.argv[1:] or ["plugin"]
    edges = graph(folders)
    loops = strongly_connected(edges)
    for component in loops:
        print(f"a loop of {len(component)} classes: {' '.join(component)}")
        print("  for example: " + " -> ".join(shortest_cycle(edges, component)))
    if not loops:
        print("no loop between classes")
    return 1 if loops else 0


if __name__ == "__main__":
    sys.exit(main())
