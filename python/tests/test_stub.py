"""The hand-written stub (deformseg/__init__.pyi) against the built package, so that it cannot drift:
the stub names every public function, class, member and constant of the package and nothing else;
every function and method has the parameters of the stub, in its order, of the same kind
(positional or keyword-only) and with the same defaults (a default `...` stands for any). Compiled
functions are read from the signature pybind11 puts first in their docstring; Python ones with
inspect."""
import ast
import inspect
import pathlib

import pytest

import deformseg

PACKAGE = pathlib.Path(deformseg.__file__).parent
STUB = ast.parse((PACKAGE / "__init__.pyi").read_text())
ANY_DEFAULT = object()  # the stub's `...` default


# ---- what the stub says ------------------------------------------------------------------------

def stub_members(body):
    """Name -> node of the definitions and annotated names of a module's or class's body (imports,
    private aliases such as _Path and overloads aside)."""
    members = {}
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            members[node.name] = node
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            members[node.target.id] = node
        elif isinstance(node, ast.Assign):
            members.update((t.id, node) for t in node.targets if isinstance(t, ast.Name))
    return {name: node for name, node in members.items() if not is_private_alias(name)}


def is_private_alias(name):
    return name.startswith("_") and not name.startswith("__")


def is_property(node):
    return any(isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list)


def parameters_of_node(node, method):
    """[(name, kind, default)] of a def in the stub or of a signature made into one; kind is
    "positional" or "keyword"; self left out of a method."""
    arguments = node.args
    positional = arguments.posonlyargs + arguments.args
    defaults = [None] * (len(positional) - len(arguments.defaults)) + list(arguments.defaults)
    out = [(a.arg, "positional", default_of(d)) for a, d in zip(positional, defaults)]
    out += [(a.arg, "keyword", default_of(d)) for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults)]
    assert arguments.vararg is None and arguments.kwarg is None, node.name
    return out[1:] if method else out


def default_of(node):
    """The default as a value: ANY_DEFAULT for `...`, inspect.Parameter.empty when there is none."""
    if node is None:
        return inspect.Parameter.empty
    if isinstance(node, ast.Constant) and node.value is Ellipsis:
        return ANY_DEFAULT
    return ast.literal_eval(node)


# ---- what the package has ----------------------------------------------------------------------

def runtime_parameters(function, method):
    """[(name, kind, default)] of a compiled or Python function, as parameters_of_node gives."""
    try:
        signature = inspect.signature(function)
    except (ValueError, TypeError):  # compiled: the signature is the docstring's first line
        return parameters_of_node(compiled_signature(function), method)
    kinds = {inspect.Parameter.POSITIONAL_ONLY: "positional", inspect.Parameter.POSITIONAL_OR_KEYWORD: "positional",
             inspect.Parameter.KEYWORD_ONLY: "keyword"}
    out = [(p.name, kinds[p.kind], p.default) for p in signature.parameters.values()]
    return out[1:] if method else out


def compiled_signature(function):
    """pybind11's `name(a: type, *, b: type = default) -> type` as the def node it reads as."""
    line = function.__doc__.splitlines()[0]
    assert line.startswith(function.__name__ + "("), (function.__name__, line)
    return ast.parse(f"def {line}: ...").body[0]


def runtime_members(cls):
    """The names a class gives its users: its attributes and those of its Python bases (not
    object's), and a dataclass's fields."""
    names = set()
    for base in cls.__mro__:
        if base is object or base.__module__ == "pybind11_builtins":
            continue
        names |= set(vars(base)) | set(getattr(base, "__annotations__", {}))
    return names


def public(names):
    return {n for n in names if not n.startswith("_")}


def package_names():
    return public(n for n in dir(deformseg) if not inspect.ismodule(getattr(deformseg, n)))


# ---- the checks --------------------------------------------------------------------------------

def assert_same_parameters(stub_node, function, where, method=False):
    stubbed, actual = parameters_of_node(stub_node, method), runtime_parameters(function, method)
    assert [(n, k) for n, k, _ in stubbed] == [(n, k) for n, k, _ in actual], where
    for (name, _, stub_default), (_, _, default) in zip(stubbed, actual):
        if stub_default is ANY_DEFAULT:
            assert default is not inspect.Parameter.empty, f"{where}: {name} has no default"
        elif isinstance(default, float) or isinstance(stub_default, float):
            assert stub_default == pytest.approx(default, rel=1e-12), f"{where}: {name}"
        else:
            assert stub_default == default and type(stub_default) is type(default), f"{where}: {name}"


def test_the_stub_names_exactly_the_public_names_of_the_package():
    stubbed = public(stub_members(STUB.body))
    assert stubbed == package_names(), (stubbed - package_names(), package_names() - stubbed)
    assert set(deformseg.__all__) == package_names()
    for dunder in ("__version__", "__all__"):
        assert dunder in stub_members(STUB.body) and hasattr(deformseg, dunder), dunder


def test_the_stub_gives_every_function_its_parameters_kinds_and_defaults():
    functions = [n for n in stub_members(STUB.body).values() if isinstance(n, ast.FunctionDef)]
    assert {f.name for f in functions} == {n for n in package_names() if not isinstance(getattr(deformseg, n), type)
                                           and callable(getattr(deformseg, n))}
    for node in functions:
        assert_same_parameters(node, getattr(deformseg, node.name), node.name)


def test_the_stub_gives_the_constants_their_types():
    for name, node in stub_members(STUB.body).items():
        if isinstance(node, ast.AnnAssign) and isinstance(node.annotation, ast.Name):
            expected = {"int": int, "str": str, "float": float, "bool": bool}[node.annotation.id]
            assert type(getattr(deformseg, name)) is expected, name


def stub_classes():
    return [n for n in stub_members(STUB.body).values() if isinstance(n, ast.ClassDef)]


def test_the_stub_gives_every_class_its_bases_and_members():
    assert {c.name for c in stub_classes()} == {n for n in package_names() if isinstance(getattr(deformseg, n), type)}
    for node in stub_classes():
        cls = getattr(deformseg, node.name)
        bases = [b.id for b in node.bases if isinstance(b, ast.Name)]
        runtime_bases = [b.__name__ for b in cls.__bases__ if b.__module__ not in ("pybind11_builtins",)]
        assert bases == [b for b in runtime_bases if b != "object"], node.name
        if issubclass(cls, BaseException):
            continue  # its attributes are the instance's: test_the_stub_gives_invalid_input_its_attributes
        members = stub_members(node.body)
        have = runtime_members(cls)
        assert set(members) <= have, (node.name, set(members) - have)
        assert public(have) <= set(members), (node.name, public(have) - set(members))
        for name, member in members.items():
            value = inspect.getattr_static(cls, name, None)
            if isinstance(member, ast.FunctionDef) and is_property(member):
                assert isinstance(value, property), f"{node.name}.{name} is not a property"
            elif isinstance(member, ast.FunctionDef):
                assert callable(value) and not isinstance(value, property), f"{node.name}.{name}"
                assert_same_parameters(member, getattr(cls, name), f"{node.name}.{name}", method=True)


def test_the_stub_gives_invalid_input_its_attributes(grid):
    node = next(c for c in stub_classes() if c.name == "InvalidInput")
    with pytest.raises(deformseg.InvalidInput) as raised:
        deformseg.strain(deformseg.Animation(*grid(2, 2, 3)), reference="sideways")
    assert set(stub_members(node.body)) == public(vars(raised.value))
    assert stub_members(next(c for c in stub_classes() if c.name == "SimilarityStopped").body) == {}


def test_a_drifted_stub_is_caught():
    """The checks fail on a stub that lost a parameter, renamed one, changed a default or a kind."""
    good = next(n for n in stub_members(STUB.body).values() if isinstance(n, ast.FunctionDef) and n.name == "strain")
    options = "measure='max-principal', normalize='gaussian', sigma=None, degenerate_tolerance=1e-12"
    for drifted in ("def strain(animation, *, reference='rest'): ...",
                    f"def strain(animation, *, reference='rest', rest_frame=0, reference_mesh=None, {options}, "
                    "thread=0): ...",
                    f"def strain(animation, *, reference='rest', rest_frame=1, reference_mesh=None, {options}, "
                    "threads=0): ...",
                    f"def strain(animation, reference='rest', rest_frame=0, reference_mesh=None, {options}, "
                    "threads=0): ..."):
        with pytest.raises(AssertionError):
            assert_same_parameters(ast.parse(drifted).body[0], deformseg.strain, "strain")
    assert_same_parameters(good, deformseg.strain, "strain")


# ---- the choices -------------------------------------------------------------------------------

# The parameters the stub gives a Literal[...], and the front end's table of choices for each
# (_deformseg._choices): every name a parameter takes is the front end's, which the tool takes too.
CHOICES = {
    ("strain", "reference"): "reference",
    ("strain", "measure"): "measure",
    ("strain", "normalize"): "normalize",
    ("frame_distances", "metric"): "metric",
    ("temporal_segmentation", "method"): "method",
    ("temporal_segmentation", "metric"): "metric",
    ("evolving_graph", "reference"): "segmentation_reference",
    ("similarity", "policy"): "policy",
    ("similarity", "alignment"): "alignment",
    ("similarity", "up"): "up",
    ("similarity_matrix", "policy"): "policy",
    ("similarity_matrix", "alignment"): "alignment",
    ("similarity_matrix", "up"): "up",
    ("describe_to_store", "up"): "up",
    ("similarity", "sides"): "sides",
    ("similarity_matrix", "sides"): "sides",
    ("describe_to_store", "sides"): "sides",
    ("open_store", "verify"): "verify",
}


def literal_values(annotation):
    """The values of the Literal[...] in an annotation (also inside Optional[...]), or None."""
    for node in ast.walk(annotation):
        if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name) and node.value.id == "Literal":
            values = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
            return [ast.literal_eval(v) for v in values]
    return None


def stub_literals():
    """(function, parameter) -> the values of its Literal[...], for every parameter that has one."""
    out = {}
    for node in stub_members(STUB.body).values():
        if isinstance(node, ast.FunctionDef):
            for argument in node.args.posonlyargs + node.args.args + node.args.kwonlyargs:
                values = literal_values(argument.annotation) if argument.annotation else None
                if values is not None:
                    out[(node.name, argument.arg)] = values
    return out


def test_every_literal_of_the_stub_is_the_front_ends_choices():
    literals = stub_literals()
    assert set(literals) == set(CHOICES)
    tables = deformseg._deformseg._choices
    assert set(tables) == set(CHOICES.values())
    for (function, parameter), table in CHOICES.items():
        assert literals[(function, parameter)] == tables[table], (function, parameter)


def test_every_choice_is_taken_and_every_other_name_refused(grid):
    """The choices are those the functions take: each one accepted, a name outside them refused
    with the list."""
    a = deformseg.Animation(*grid(3, 3, 6))
    tables = deformseg._deformseg._choices
    for measure in tables["measure"]:
        assert deformseg.strain(a, measure=measure).shape == (6, a.num_faces)
    for method in tables["method"]:
        assert deformseg.temporal_segmentation(a, method=method)[0][0] == 0
    for up in tables["up"]:
        assert 0 <= deformseg.similarity(a, a, up=up, significance=0).value <= 1
    for sides in tables["sides"]:
        assert deformseg.similarity(a, a, sides=sides, significance=0).value == 1
    with pytest.raises(deformseg.InvalidInput, match="measure must be 'max-principal', 'green-lagrange', "
                                                     "'frobenius' or 'area-ratio', got 'max'"):
        deformseg.strain(a, measure="max")
