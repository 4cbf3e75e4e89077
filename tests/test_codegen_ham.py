"""generated/ is deterministic (same bytes under different PYTHONHASHSEED), fresh, and the
check mode reports a stale file with a diff."""
import json
import os
import subprocess
import sys

import pytest

from zener_sym import codegen

_RENDER = ("import json, sys; from zener_sym import codegen; "
           "json.dump(codegen.render_all(), sys.stdout, sort_keys=True)")


@pytest.fixture(scope="module")
def rendered_twice():
    procs = []
    for seed in ("0", "4242"):
        env = dict(os.environ, PYTHONHASHSEED=seed)
        procs.append(subprocess.Popen([sys.executable, "-c", _RENDER], env=env,
                                      stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True))
    outs = []
    for p in procs:
        out, err = p.communicate(timeout=300)
        assert p.returncode == 0, err
        outs.append(json.loads(out))
    return outs


@pytest.mark.slow
def test_deterministic_under_hash_seeds(rendered_twice):
    a, b = rendered_twice
    assert set(a) >= {"ham0_numpy.py", "ham1_numpy.py", "ham0_mpmath.py", "ham1_mpmath.py"}
    for name in a:
        assert a[name] == b[name], name


@pytest.mark.slow
def test_committed_generated_is_fresh(rendered_twice):
    assert codegen.diff(rendered_twice[0], codegen.generated_dir()) == ""


@pytest.mark.slow
def test_stale_file_gives_a_diff(rendered_twice, tmp_path):
    rendered = rendered_twice[0]
    for name, text in rendered.items():
        (tmp_path / name).write_text(text)
    stale = tmp_path / "ham1_numpy.py"
    stale.write_text(stale.read_text().replace("def delta(", "def delta_old("))
    d = codegen.diff(rendered, tmp_path)
    assert "-def delta_old(" in d and "+def delta(" in d and "committed/ham1_numpy.py" in d


def test_headers_name_sources_hash_and_sympy():
    import sympy

    for name in ("ham0_numpy.py", "ham1_numpy.py", "ham0_mpmath.py", "ham1_mpmath.py"):
        text = (codegen.generated_dir() / name).read_text()
        head = text.split('"""')[1]
        assert "DO NOT EDIT" in head
        assert "zener_sym.codegen.ham_exprs" in head
        assert f"SymPy version: {sympy.__version__}" in head
        assert f"Derivation inputs hash: {codegen.inputs_hash()}" in head


def test_numpy_kernels_do_not_import_mpmath():
    for name in ("ham0_numpy.py", "ham1_numpy.py"):
        text = (codegen.generated_dir() / name).read_text()
        assert "import mpmath" not in text and "mpmath." not in text


@pytest.mark.slow
def test_cli_generate_check_passes(capsys):
    """What CI and the hook run: `zener-sym generate --check` on the committed tree."""
    from zener_sym.cli import main

    assert main(["generate", "--check"]) == 0
    assert "up to date" in capsys.readouterr().out
