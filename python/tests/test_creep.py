"""creep(): the command line's numbers bit for bit, numpy broadcasting, its errors."""

import math

import numpy as np
import pytest

import wheelwear

# The paper's reference patch (Liu, Fu & Bruni 2022, Fig. 9): pure spin on an SDEC.
PATCH = dict(a=4.25e-3, b=4.25e-3, psi=0.6, N=37830.0, G=80e9, nu=0.25, mu=0.35)


def cli_args(method, **kw):
    args = ["creep", "--method", method]
    for key, value in kw.items():
        args += [f"--{key.replace('_', '-')}", repr(float(value)) if isinstance(value, float) else value]
    return args


@pytest.mark.parametrize("method", ["fastsim-sdec", "fastsim-eqe", "linear-sdec", "she-sdec",
                                    "table", "best"])
@pytest.mark.parametrize("creepages", [dict(phi=1.0), dict(vx=1e-3, vy=-5e-4, phi=0.3)])
def test_scalar_equals_the_command_line_bit_for_bit(cli, method, creepages):
    # Same code path (cli/creep_request.cpp), JSON printed with 17 significant digits: equal.
    kw = {**PATCH, **creepages}
    expected = cli(*cli_args(method, **kw))
    got = wheelwear.creep(method, **kw)
    assert isinstance(got.Fx, float) and isinstance(got.Fy, float)
    assert got.Fx == expected["Fx"]
    assert got.Fy == expected["Fy"]
    assert got.Fx_muN == expected["Fx_muN"]


def test_exact_equals_the_command_line(cli):
    kw = {**PATCH, "vx": 2e-3, "phi": 0.5}
    expected = cli(*cli_args("exact", **kw), "--exact-grid", "16")
    got = wheelwear.creep("exact", exact_grid=16, **kw)
    assert (got.Fx, got.Fy, got.Mz) == (expected["Fx"], expected["Fy"], expected["Mz"])
    assert got.rigid_slip_work == expected["rigid_slip_work"]
    assert got.status == expected["status"] == "converged"


def test_best_beyond_the_table_equals_the_command_line(cli):
    # a/b = 20 at nu = 0.28 lies beyond the book of tables (its nu = 0.25 group reaches 25): the
    # exact theory answers by default, FASTSIM-SDEC when asked, each as the command line gives it.
    kw = dict(a=19e-3, b=0.95e-3, psi=0.3, phi=0.5, N=37830.0, mu=0.35, nu=0.28)
    exact = cli(*cli_args("best", **kw))
    got = wheelwear.creep("best", **kw)
    assert (got.Fx, got.Fy, got.Mz) == (exact["Fx"], exact["Fy"], exact["Mz"])
    assert not got.from_table and got.status == "converged"
    runs = wheelwear.creep("best", beyond_table="fastsim-sdec", **kw)
    fastsim = wheelwear.creep("fastsim-sdec", **kw)
    assert (runs.Fx, runs.Fy) == (fastsim.Fx, fastsim.Fy)
    with pytest.raises(ValueError, match="--beyond-table"):
        wheelwear.creep("fastsim-sdec", beyond_table="exact", **kw)


def test_best_inside_the_table_is_the_exact_theory_unless_the_table_is_asked_for():
    # a/b = 1 lies inside the book of tables: best solves the exact theory on the grid that
    # resolves the patch (40 x 40 here, the exact method's default), the table's totals only
    # with inside_table="table".
    kw = dict(a=5e-3, b=5e-3, psi=0.4, vx=1e-3, vy=-2e-4, phi=0.4, N=40e3, mu=0.35)
    best = wheelwear.creep("best", **kw)
    exact = wheelwear.creep("exact", **kw)
    assert (best.Fx, best.Fy, best.Mz) == (exact.Fx, exact.Fy, exact.Mz)
    assert not best.from_table
    tabled = wheelwear.creep("best", inside_table="table", **kw)
    table = wheelwear.creep("table", **kw)
    assert tabled.from_table and (tabled.Fx, tabled.Fy) == (table.Fx, table.Fy)
    with pytest.raises(ValueError, match="--inside-table"):
        wheelwear.creep("exact", inside_table="table", **kw)


def test_rigid_slip_work_is_minus_the_power_of_the_creep_forces():
    # -(Fx vx + Fy vy + Mz phi) by definition, for every method with a spin moment.
    vx, vy, phi = 1e-3, -4e-4, 0.6
    for method in ("fastsim-sdec", "table", "fastsim-eqe"):
        r = wheelwear.creep(method, a=5e-3, b=4e-3, vx=vx, vy=vy, phi=phi, N=4e4)
        assert r.rigid_slip_work == pytest.approx(-(r.Fx * vx + r.Fy * vy + r.Mz * phi),
                                                  rel=1e-12)
        assert r.rigid_slip_work > 0  # friction dissipates


def test_an_array_gives_the_broadcast_shape_and_each_element_its_scalar_answer():
    phi = np.linspace(-2.0, 2.0, 7)
    vx = np.array([[0.0], [1e-3]])  # (2, 1) against (7,): (2, 7)
    got = wheelwear.creep(a=6e-3, b=3e-3, vx=vx, phi=phi, N=50e3)
    assert got.Fx.shape == (2, 7) and got.Fy.shape == (2, 7) and got.from_table.shape == (2, 7)
    compared = 0
    for i in range(2):
        for j in range(7):
            one = wheelwear.creep(a=6e-3, b=3e-3, vx=float(vx[i, 0]), phi=float(phi[j]), N=50e3)
            assert got.Fx[i, j] == one.Fx and got.Fy[i, j] == one.Fy
            compared += 1
    assert compared == 14


def test_the_creep_curve_is_odd_in_the_spin():
    # Reversing every creepage reverses the forces (Kalker's theory is odd in them): FASTSIM on
    # an ellipse keeps that exactly up to rounding.
    phi = np.linspace(0.1, 2.0, 20)
    plus = wheelwear.creep(a=5e-3, b=4e-3, phi=phi, N=40e3)
    minus = wheelwear.creep(a=5e-3, b=4e-3, phi=-phi, N=40e3)
    np.testing.assert_allclose(minus.Fy, -plus.Fy, rtol=1e-12, atol=1e-9)


def test_threads_do_not_change_the_numbers():
    vy = np.linspace(-3e-3, 3e-3, 300)
    one = wheelwear.creep("best", a=6e-3, b=3e-3, psi=0.3, vy=vy, N=50e3, threads=1)
    two = wheelwear.creep("best", a=6e-3, b=3e-3, psi=0.3, vy=vy, N=50e3, threads=2)
    assert np.array_equal(one.Fy, two.Fy) and np.array_equal(one.Fx, two.Fx)


def test_linear_theory_has_no_spin_moment():
    got = wheelwear.creep("linear-sdec", a=5e-3, b=5e-3, vx=1e-4, N=40e3)
    assert math.isnan(got.Mz)


@pytest.mark.parametrize(
    "flags, kwargs",
    [
        (["--method", "exact", "--nx", "10"], dict(method="exact", nx=10)),
        (["--method", "exact", "--bound", "parabolic"], dict(method="exact", bound="parabolic")),
        (["--method", "linear-sdec", "--target-error", "0.01"],
         dict(method="linear-sdec", target_error=0.01)),
        (["--N", "-1e4"], dict(N=-1e4)),
        (["--a", "nan"], dict(a=float("nan"))),
        (["--exact-grid", "20"], dict(exact_grid=20)),
        (["--method", "exact", "--exact-grid", "4"], dict(method="exact", exact_grid=4)),
    ],
)
def test_input_errors_raise_value_error_with_the_command_lines_message(cli, flags, kwargs):
    base = {"a": 4e-3, "b": 4e-3, "N": 1e4}
    args = ["creep", *flags]
    for key, value in base.items():
        if f"--{key}" not in flags:
            args += [f"--{key}", str(value)]
    expected = cli.error(*args)
    with pytest.raises(ValueError) as error:
        wheelwear.creep(**{**base, **kwargs})
    assert str(error.value) == expected


@pytest.mark.parametrize(
    "flags, kwargs",
    [
        (["--method", "fastsim-x"], dict(method="fastsim-x")),
        (["--bound", "flat"], dict(bound="flat")),
        (["--scheme", "third-order"], dict(scheme="third-order")),
        (["--nx", "10", "--target-error", "0.01"], dict(nx=10, target_error=0.01)),
    ],
)
def test_names_outside_the_choices_are_refused_as_the_command_lines_parser_does(cli, flags,
                                                                                 kwargs):
    expected = cli.error("creep", *flags, "--a", "4e-3", "--b", "4e-3", "--N", "1e4")
    with pytest.raises(ValueError) as error:
        wheelwear.creep(**{"a": 4e-3, "b": 4e-3, "N": 1e4, **kwargs})
    assert str(error.value) == expected


def test_implausible_inputs_warn_once():
    with pytest.warns(RuntimeWarning) as record:
        wheelwear.creep(a=4e-3, b=4e-3, vx=np.full(10, 0.3), N=1e4)
    assert len([w for w in record if "--vx" in str(w.message)]) == 1
