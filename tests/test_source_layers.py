"""The solver's source tree keeps the layers solver/README.md maps: each file includes only its own layer
and the layers above it in the README's table, and every source file the docs name exists."""
import ast
import re

LAYER_ROW = re.compile(r"^\| `(\w+)/` \|", flags=re.M)
INCLUDE = re.compile(r'^#include "([\w/.]+)"', flags=re.M)
GENERATED = {"io/version.hpp": "io/version.hpp.in"}  # CMake writes it from the template


def layers(root):
    order = LAYER_ROW.findall((root / "solver" / "README.md").read_text())
    assert len(order) >= 5, order  # the table is there: the test is not vacuous
    return order


def sources(root):
    src = root / "solver" / "src"
    return src, sorted(p for p in src.rglob("*") if p.is_file())


def test_every_source_file_sits_in_a_mapped_layer(root):
    order = layers(root)
    src, files = sources(root)
    assert {p.name for p in src.iterdir() if p.is_dir()} == set(order)
    for path in files:
        rel = path.relative_to(src)
        assert len(rel.parts) == 2 and rel.parts[0] in order, f"solver/src/{rel} is outside the layers"


def test_includes_name_an_existing_file_of_the_same_or_an_earlier_layer(root):
    order = layers(root)
    src, files = sources(root)
    checked = 0
    for path in files:
        layer = path.relative_to(src).parts[0]
        for target in INCLUDE.findall(path.read_text()):
            where = src / GENERATED.get(target, target)
            assert where.exists(), f"solver/src/{layer}/{path.name} includes {target}, which does not exist"
            their = target.split("/")[0]
            assert their in order and order.index(their) <= order.index(layer), \
                f"solver/src/{layer}/{path.name} ({layer}) includes {target} from a later layer ({their})"
            checked += 1
    assert checked > 100


def test_source_files_the_docs_name_exist(root):
    order = "|".join(layers(root))
    named = re.compile(rf"`((?:{order})/[\w.]+)`")
    src = root / "solver" / "src"
    docs = [root / "README.md", root / "solver" / "README.md", *sorted((root / "docs").glob("*.md"))]
    found = 0
    for doc in docs:
        for name in named.findall(doc.read_text()):
            assert (src / name).exists(), f"{doc.relative_to(root)} names {name}, not in solver/src"
            found += 1
    assert found > 30


# The laws only a fluid model uses (engine/fluid_model.hpp): the engine's step reaches them through it.
FLUID_LAWS = {"physics/fluid_pairs.hpp", "physics/wall_fluid.hpp", "physics/pressure_coupling.hpp",
              "physics/mass_transfer.hpp", "physics/pressure_closure.hpp", "physics/volume_closure.hpp",
              "physics/lennard_jones.hpp", "physics/kernel.hpp", "physics/sph_terms.hpp",
              "physics/cavity_pressure.hpp"}


def test_the_engine_reaches_the_fluid_only_through_its_model(root):
    engine = root / "solver" / "src" / "engine"
    for name in ("simulation.hpp", "simulation.cpp", "energy_account.hpp", "energy_account.cpp", "quasi_static.cpp"):
        direct = set(INCLUDE.findall((engine / name).read_text()))
        assert not direct & FLUID_LAWS, f"engine/{name} includes {sorted(direct & FLUID_LAWS)}: a fluid model's laws"
    used = set(INCLUDE.findall((engine / "sph_fluid.cpp").read_text() + (engine / "sph_fluid.hpp").read_text()))
    assert len(used & FLUID_LAWS) >= 6, used  # the fluid's laws are there: the test is not vacuous
    cavity = set(INCLUDE.findall((engine / "cavity_fluid.cpp").read_text()))
    assert {"physics/cavity_pressure.hpp", "physics/mass_transfer.hpp"} <= cavity, cavity


def analysis_imports(root):
    """{module: set of analysis modules it imports} for analysis/*.py, and every import statement found
    below a module's top level as (module, line)."""
    graph, nested = {}, []
    for path in sorted((root / "analysis").glob("*.py")):
        tree = ast.parse(path.read_text())
        top = set(id(node) for node in tree.body)
        graph[path.stem] = set()
        for node in ast.walk(tree):
            if not isinstance(node, (ast.Import, ast.ImportFrom)):
                continue
            if id(node) not in top:
                nested.append((path.stem, node.lineno))
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                [f"{node.module}.{a.name}" if node.module == "analysis" else node.module for a in node.names]
            graph[path.stem] |= {n.split(".")[1] for n in names if n.startswith("analysis.")}
    return graph, nested


def test_analysis_imports_at_the_top_of_each_module_and_in_no_circle(root):
    graph, nested = analysis_imports(root)
    assert len(graph) > 10 and sum(map(len, graph.values())) > 15, graph  # the graph was read
    assert not nested, f"imports inside a function or block (an import circle hides there): {nested}"
    for module in graph:  # depth-first from each module: does any path lead back to it?
        seen, todo = set(), list(graph[module])
        while todo:
            other = todo.pop()
            assert other != module, f"analysis/{module}.py imports itself through {sorted(seen)}"
            if other not in seen:
                seen.add(other)
                todo.extend(graph.get(other, ()))
