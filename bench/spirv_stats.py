#!/usr/bin/env python3
"""Static instruction counts of the generated SPIR-V (docs/shaders.md, "Measured").

    python3 bench/spirv_stats.py SHADER_DIR [SHADER_DIR ...]

For each pass of max 64 (the passes of ctess_mesh_64.layout.json, in its order): the instructions of the per-patch setup an emit workgroup runs (the call tree of
`record_patch`, as glslang emits it, one function per GLSL function), and the whole pass after `spirv-opt -O`
(everything inlined into main). Then, per pattern, the call tree of the function one invocation runs per
output element (CP: patch_vertex / patch_triangle, uniform density: uniform_vertex / uniform_triangle, split:
split_vertex in the split_points pass / uniform_triangle of the leaf's pattern): the
static instructions per output vertex and per output triangle, beside the per-patch setup above (surface
evaluation excluded; loops counted once), and for the displaced passes the call tree of the displacement one
invocation runs per output vertex (scalar: a height along the direction, vector: an RGB offset in the tangent
frame; docs/algorithm.md §8). Needs spirv-dis and spirv-opt (Debian spirv-tools).
"""
import json
import re
import subprocess
import sys
import tempfile

# The function one invocation runs per output element of a pass, per pattern (shaders/ctess_mesh.comp.glsl).
# A split leaf's vertex is split_vertex in the split_points pass (its vertex passes read the result).
ELEMENT = {"emit_vertices": {"cp": "patch_vertex", "uniform": "uniform_vertex"},
           "split_points": {"uniform split": "split_vertex"},
           "emit_triangles": {"cp": "patch_triangle", "uniform": "uniform_triangle", "uniform split": "uniform_triangle"}}
# The displacement one invocation of a displaced pass runs per output vertex.
DISPLACEMENT = {"emit_displaced_vertices": "displace_triangle_point",
                "emit_displaced_quad_vertices": "displace_quad_point",
                "emit_vector_displaced_vertices": "displace_triangle_vector",
                "emit_vector_displaced_quad_vertices": "displace_quad_vector"}
NOT_INSTRUCTIONS = {"OpFunction", "OpFunctionParameter", "OpFunctionEnd", "OpLabel", "OpLine", "OpNoLine"}


def functions(spv):
    """name -> (instruction count, set of callees)"""
    text = subprocess.run(["spirv-dis", "--no-color", spv], check=True, capture_output=True, text=True).stdout
    out, name = {}, None
    for line in text.splitlines():
        m = re.match(r"\s*(%\S+) = OpFunction ", line)
        if m:
            name = m.group(1)
            out[name] = [0, set()]
            continue
        if name is None:
            continue
        op = re.search(r"\b(Op\w+)", line)
        if not op:
            continue
        if op.group(1) == "OpFunctionEnd":
            name = None
            continue
        if op.group(1) not in NOT_INSTRUCTIONS:
            out[name][0] += 1
        call = re.search(r"OpFunctionCall %\S+ (%\S+)", line)
        if call:
            out[name][1].add(call.group(1))
    return out


def function_named(spv, name):
    """The %id of the function whose GLSL name (OpName up to its parenthesis) is name, or None."""
    text = subprocess.run(["spirv-dis", "--no-color", spv], check=True, capture_output=True, text=True).stdout
    for m in re.finditer(r'OpName (%\S+) "([^"(]*)\(', text):
        if m.group(2) == name:
            return m.group(1)
    return None


def tree_size(funcs, root):
    seen, stack = set(), [root]
    while stack:
        f = stack.pop()
        if f in seen or f not in funcs:
            continue
        seen.add(f)
        stack.extend(funcs[f][1])
    return sum(funcs[f][0] for f in seen), len(seen)


def optimized_size(spv):
    with tempfile.NamedTemporaryFile(suffix=".spv") as tmp:
        subprocess.run(["spirv-opt", "-O", spv, "-o", tmp.name], check=True)
        return sum(n for n, _ in functions(tmp.name).values())


def passes(d):
    """The pass names of max 64, from the generated layout (one source with the hosts)."""
    try:
        with open(f"{d}/ctess_mesh_64.layout.json") as f:
            return [x["name"] for x in json.load(f)["passes"]]
    except FileNotFoundError:
        sys.exit(f"spirv_stats.py: {d} has no ctess_mesh_64.layout.json (shaders from before it was generated: "
                 "check out this script from the same commit)")


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    print("| shaders | pass | record_patch call tree (instructions, functions) | whole pass after spirv-opt -O |")
    print("|---|---|---|---|")
    for d in sys.argv[1:]:
        for p in passes(d):
            spv = f"{d}/ctess_mesh_64_{p}.spv"
            funcs = functions(spv)
            root = next((f for f in funcs if f.startswith("%record_patch")), None)
            setup = "—" if root is None else "%d, %d" % tree_size(funcs, root)
            print(f"| {d} | {p} | {setup} | {optimized_size(spv)} |")
    print()
    print("| shaders | pass | pattern | per-element call tree (instructions, functions) |")
    print("|---|---|---|---|")
    for d in sys.argv[1:]:
        for p, by_pattern in ELEMENT.items():
            spv = f"{d}/ctess_mesh_64_{p}.spv"
            funcs = functions(spv)
            for pattern, name in by_pattern.items():
                root = function_named(spv, name)
                size = "—" if root is None else "%d, %d" % tree_size(funcs, root)
                print(f"| {d} | {p} | {pattern} `{name}` | {size} |")
    print()
    print("| shaders | pass | displacement per output vertex (instructions, functions) |")
    print("|---|---|---|")
    for d in sys.argv[1:]:
        for p, name in DISPLACEMENT.items():
            spv = f"{d}/ctess_mesh_64_{p}.spv"
            root = function_named(spv, name)
            size = "—" if root is None else "%d, %d" % tree_size(functions(spv), root)
            print(f"| {d} | {p} | `{name}` | {size} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
