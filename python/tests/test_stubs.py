"""The type stubs (__init__.pyi) name what the module has, with its defaults."""

import ast
import os

import holefill

STUB = os.path.join(os.path.dirname(holefill.__file__), "__init__.pyi")


def stub_tree():
    with open(STUB, encoding="utf-8") as source:
        return ast.parse(source.read())


def keyword_defaults(function):
    args = function.args
    return {a.arg: ast.literal_eval(d) for a, d in zip(args.kwonlyargs, args.kw_defaults)
            if d is not None}


def test_the_stubs_name_every_public_name():
    tree = stub_tree()
    names = {node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    names |= {t.id for node in tree.body if isinstance(node, ast.AnnAssign)
              for t in [node.target]}
    assert set(holefill.__all__) <= names


def test_fills_stub_defaults_are_the_modules():
    functions = {node.name: node for node in stub_tree().body if isinstance(node, ast.FunctionDef)}
    defaults = keyword_defaults(functions["fill"])
    defaults.pop("progress")
    assert defaults == holefill.FILL_OPTIONS


def test_help_lists_every_option():
    for name in holefill.FILL_OPTIONS:
        assert "    " + name + " (" in holefill.fill.__doc__
        assert "    " + name + " (" in holefill.Fill.__doc__ or name in ("max_boundary", "stage")
