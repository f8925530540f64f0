"""The Python module against the gkt program: the same scene gives the same columns, bit for bit,
and the same one-line errors (issue 19 item 3)."""

import concurrent.futures
import fractions
import math
import os
import tempfile
import warnings

import numpy as np
import pytest

import gkt
from conftest import SCENES, cli_columns, cli_error, run_cli


def assert_same_table(columns, cli):
    """The module's columns equal the CLI's CSV cells: same names in the same order, and every
    number the same double (the CSV holds shortest round-trip decimals)."""
    assert list(columns) == list(cli)
    for name, cells in cli.items():
        got = columns[name]
        assert got.shape == (len(cells),), name
        if name == "order":
            assert got.dtype == np.int64
            assert got.tolist() == [int(c) for c in cells]
        else:
            want = np.array([float(c) for c in cells])
            np.testing.assert_array_equal(got, want, err_msg=name)


# ---- tables: the same scene through the module and the program --------------------------------


@pytest.mark.parametrize(
    "scene, overrides",
    [
        ("hard_spheres_convergence.toml", ["order={from=1, to=8, points=8}"]),
        ("navier_stokes_first_sonine.toml", []),
        ("navier_stokes_first_sonine.toml", ['scheme="modified"', "dimension=2"]),
        ("smooth_inelastic_orders.toml", ["alpha=[0.9, 0.5]", "order={from=1, to=4, points=4}"]),
        ("tracer_diffusion.toml", ["alpha=[1, 0.7]"]),
        ("mixture_hcs.toml", ["alpha=0.8", "packing_fraction=[0, 0.2]"]),
        ("enskog_first_sonine.toml", []),
    ],
)
def test_table_equals_cli_on_the_same_scene(scene, overrides):
    path = SCENES / scene
    args = [a for o in overrides for a in ("--set", o)]
    assert_same_table(gkt.table(path, overrides=overrides), cli_columns("table", path, *args))


def test_scene_as_path_text_and_dict_agree():
    path = SCENES / "navier_stokes_first_sonine.toml"
    from_path = gkt.table(str(path))
    from_text = gkt.table(path.read_text())
    from_dict = gkt.table(
        {
            "model": "smooth-inelastic",
            "dimension": 3,
            "hcs": "linear",
            "alpha": np.array([1, 0.9, 0.8, 0.7, 0.6, 0.5]),
            "order": 1,
            "coefficients": ["shear_viscosity", "thermal_conductivity", "density_heat_coefficient", "cooling_rate"],
        }
    )
    for other in (from_text, from_dict):
        assert list(other) == list(from_path)
        for name in from_path:
            np.testing.assert_array_equal(other[name], from_path[name])


def test_dict_with_species_and_range_equals_cli():
    scene = {
        "model": "mixture",
        "alpha": 0.9,
        "order": 1,
        "species": [
            {"name": "reference", "mass": 1, "diameter": 1, "fraction": 0.5},
            {"mass": {"from": 0.5, "to": 2, "points": 3}, "diameter": 2, "fraction": 0.5},
        ],
    }
    text = """model = "mixture"
alpha = 0.9
order = 1
[[species]]
name = "reference"
mass = 1
diameter = 1
fraction = 0.5
[[species]]
mass = { from = 0.5, to = 2, points = 3 }
diameter = 2
fraction = 0.5
"""
    got = gkt.table(scene)
    assert got["mass_2"].tolist() == [0.5, 1.25, 2]
    assert_same_table(got, cli_columns("table", write_scene(text)))


def test_exact_cells_are_fractions_equal_to_cli_exact():
    path = SCENES / "hard_spheres_exact.toml"
    got = gkt.table(path, exact=True)
    cli = cli_columns("table", path, "--exact")
    assert list(got) == list(cli)
    assert got["shear_viscosity"].dtype == object
    assert got["shear_viscosity"].tolist() == [fractions.Fraction(c) for c in cli["shear_viscosity"]]
    assert got["shear_viscosity"][got["order"] == 2][0] == fractions.Fraction(205, 202)  # Chapman-Cowling


def test_stability_equals_cli_stability():
    path = SCENES / "hcs_stability.toml"
    overrides = ["alpha=[0.6, 0.9]", "order=2"]
    cli = cli_columns("stability", path, "--set", overrides[0], "--set", overrides[1])
    assert "critical_length" in cli
    assert_same_table(gkt.stability(path, overrides=overrides), cli)


@pytest.mark.parametrize("scene", ["cooling_constant_alpha.toml", "cooling_viscoelastic.toml"])
def test_evolve_equals_cli_evolve(scene):
    path = SCENES / scene
    got = gkt.evolve(path, overrides=["points=6"])
    assert_same_table(got, cli_columns("evolve", path, "--set", "points=6"))
    assert np.all(np.diff(got["temperature"]) < 0)  # a cooling gas


DSMC_SMALL = ["particles=1000", "runs=4", "collisions_per_particle=20"]


@pytest.mark.parametrize(
    "scene, extra",
    [("dsmc_hcs.toml", []), ("dsmc_mixture.toml", []), ("dsmc_hcs.toml", ["output={haff=true}"])],
)
def test_dsmc_equals_cli_dsmc(scene, extra):
    path = SCENES / scene
    overrides = DSMC_SMALL + extra
    cli = cli_columns("dsmc", path, *[a for o in overrides for a in ("--set", o)])
    got = gkt.dsmc(path, overrides=overrides)
    assert_same_table(got, cli)
    if not extra:  # a summary: one row, every coefficient with a positive standard error
        for name in got:
            if not name.endswith("_error"):
                assert got[name].shape == (1,) and got[name + "_error"][0] > 0, name


def test_dsmc_does_not_depend_on_jobs_and_takes_a_dict():
    scene = {"model": "smooth-inelastic", "dimension": 2, "alpha": 0.7, "particles": 500, "relaxation": 5,
             "collisions_per_particle": 10, "batches": 5, "runs": 3, "seed": 7}
    one = gkt.dsmc(scene)
    two = gkt.dsmc(scene, jobs=2)
    assert list(one) == list(two) == ["a2", "a2_error", "a3", "a3_error", "cooling_rate", "cooling_rate_error"]
    for name in one:
        np.testing.assert_array_equal(one[name], two[name], err_msg=name)
    other_seed = gkt.dsmc(scene, overrides=["seed=8"])
    assert other_seed["a2"][0] != one["a2"][0]


def test_bad_dsmc_scene_raises_the_cli_message():
    path = SCENES / "dsmc_hcs.toml"
    for override in ["alpha=1.5", "particles=1", 'model="gravity-column"', "runs=0"]:
        message = cli_error("dsmc", path, "--set", override)
        with pytest.raises(ValueError) as raised:
            gkt.dsmc(path, overrides=[override])
        assert str(raised.value) == message
    with pytest.raises(ValueError, match=r"^jobs: must be an integer in \[1, 64\], got 0$"):
        gkt.dsmc(path, jobs=0)


@pytest.mark.parametrize("dimension", [2, 3])
def test_uniform_shear_dsmc_near_grad(dimension):
    grad = gkt.table({"model": "uniform-shear", "dimension": dimension, "alpha": 0.7, "order": 1})
    run = gkt.uniform_shear_dsmc(0.7, 0.6, dimension=dimension, particles=1000, relaxation=20, batches=5,
                                 collisions_per_batch=5, seed=3)
    assert list(run) == ["reduced_shear_rate", "stress_xx", "stress_yy", "stress_zz", "stress_xy", "temperature"]
    assert all(v.shape == (5,) for v in run.values())
    trace = run["stress_xx"] + run["stress_yy"] + run["stress_zz"]  # P_ii/(2nT) = d/2
    np.testing.assert_allclose(trace, dimension / 2, rtol=1e-12)
    if dimension == 2:
        assert np.all(run["stress_zz"] == 0)
    for name in ("reduced_shear_rate", "stress_xx", "stress_yy", "stress_xy"):  # Grad is within a few %
        np.testing.assert_allclose(run[name].mean(), grad[name][0], rtol=0.15, err_msg=name)
    again = gkt.uniform_shear_dsmc(0.7, 0.6, dimension=dimension, particles=1000, relaxation=20, batches=5,
                                   collisions_per_batch=5, seed=3)
    np.testing.assert_array_equal(again["stress_xy"], run["stress_xy"])


def test_uniform_shear_dsmc_errors_name_the_field():
    with pytest.raises(ValueError, match="^alpha: "):
        gkt.uniform_shear_dsmc(1.0, 0.3)
    with pytest.raises(ValueError, match="^shear_rate: "):
        gkt.uniform_shear_dsmc(0.9, 0.0)
    with pytest.raises(ValueError, match="^dimension: "):
        gkt.uniform_shear_dsmc(0.9, 0.3, dimension=4)


def test_unreached_tolerance_warns_with_the_cli_line():
    path = SCENES / "tracer_diffusion.toml"
    overrides = ["alpha=0.7", "tolerance=1e-12", "species=[{mass=[0.5, 5], diameter=1.5, fraction=0}, {mass=1, diameter=1, fraction=1}]"]
    code, _, err = run_cli("table", path, *[a for o in overrides for a in ("--set", o)])
    assert code == 0 and len(err.strip().splitlines()) == 2
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        gkt.table(path, overrides=overrides)
    assert [str(w.message) for w in caught] == err.strip().splitlines()
    assert all(w.category is UserWarning for w in caught)


def test_models_lists_what_gkt_models_prints():
    code, out, _ = run_cli("models")
    assert code == 0
    models = gkt.models()
    assert list(models) == [line.split(":")[0] for line in out.splitlines() if not line.startswith(" ")]
    for name, m in models.items():
        assert f"{name}: {m['description']}" in out
        assert "  coefficients: " + " ".join(m["coefficients"]) in out
        assert "  parameters: " + " ".join(f"{p} ({a})" for p, a in m["parameters"].items()) in out
        assert m["max_order"] >= 1
    assert "shear_viscosity" in models["smooth-inelastic"]["coefficients"]


# ---- errors: ValueError with the CLI's one-line message ------------------------------------------

BAD_SCENES = [
    'model = "smooth-inelastic"\nalpha = 1.5\norder = 2\n',
    'model = "smooth-inelastic"\nalpha = 0.9\n',
    'model = "smooth-inelastic"\nalpha = 0.9\norder = 2\ncolour = 3\n',
    'model = "smooth-inelastic"\nalpha = 0.9\norder = 2\ncoefficients = ["viscosity"]\n',
    'model = "granular-soup"\norder = 2\n',
    'model = "smooth-inelastic"\nalpha = { from = 0.5, to = 1 }\norder = 2\n',
    'model = "mixture"\nalpha = 0.9\norder = 1\n[[species]]\nmass = 1\ndiameter = 1\n',
    'model = "smooth-inelastic"\nalpha = 0.9\norder = 2\npacking_fraction = 0.6\n',
    'model = "smooth-inelastic"\nalpha = [0.9, \n',
]


def write_scene(text):
    """Returns the path of a scratch scene file holding `text` (removed when the test ends)."""
    handle = tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False)
    with handle:
        handle.write(text)
    write_scene.paths.append(handle.name)
    return handle.name


write_scene.paths = []


@pytest.fixture(autouse=True)
def _remove_scratch_scenes():
    yield
    while write_scene.paths:
        os.unlink(write_scene.paths.pop())


@pytest.mark.parametrize("text", BAD_SCENES)
def test_bad_scene_raises_the_cli_message(text):
    path = write_scene(text)
    message = cli_error("table", path)
    with pytest.raises(ValueError) as from_path:
        gkt.table(path)
    assert str(from_path.value) == message
    with pytest.raises(ValueError) as from_text:
        gkt.table(text)
    assert str(from_text.value) == message.replace(path, "<string>")


def test_bad_evolve_scene_and_override_raise_the_cli_message():
    path = SCENES / "cooling_constant_alpha.toml"
    for override in ["alpha=0", "points=2.5", "times=[2, 1]", "t_end=-1"]:
        message = cli_error("evolve", path, "--set", override)
        with pytest.raises(ValueError, match="^" + message.split(":")[0] + ":") as raised:
            gkt.evolve(path, overrides=[override])
        assert str(raised.value) == message


def test_missing_file_and_bad_types():
    message = cli_error("table", "no/such/scene.toml")
    with pytest.raises(ValueError) as raised:
        gkt.table("no/such/scene.toml")
    assert str(raised.value) == message
    with pytest.raises(ValueError, match="^scene: must be a path, TOML text or a dict, got int$"):
        gkt.table(3)
    with pytest.raises(ValueError, match="^alpha: unsupported value of type object"):
        gkt.table({"model": "smooth-inelastic", "alpha": object(), "order": 1})
    with pytest.raises(ValueError, match="^scene: keys must be strings, got int$"):
        gkt.table({1: 2})
    with pytest.raises(ValueError, match="^species.mass: unsupported value of type object"):
        gkt.table({"model": "mixture", "alpha": 0.9, "order": 1, "species": [{"mass": object()}]})
    with pytest.raises(ValueError, match='^alpha.x: unknown key for model "smooth-inelastic"'):
        gkt.table({"model": "smooth-inelastic", "alpha.x": 0.9, "order": 1})
    with pytest.raises(ValueError, match="^--set: expected KEY=VALUE"):
        gkt.table(SCENES / "navier_stokes_first_sonine.toml", overrides=["order"])


# ---- per-cell calls over arrays ----------------------------------------------------------------


def test_first_sonine_equals_the_order_one_linear_table():
    alpha = np.linspace(0.3, 1.0, 8)
    cells = gkt.first_sonine(alpha)
    table = gkt.table(
        {
            "model": "smooth-inelastic",
            "hcs": "linear",
            "alpha": alpha,
            "order": 1,
            "coefficients": ["a2", "cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"],
        }
    )
    for name, values in cells.items():
        assert values.shape == alpha.shape
        np.testing.assert_allclose(values, table[name], rtol=1e-12, atol=1e-14, err_msg=name)


def test_first_sonine_keeps_shape_and_matches_single_calls():
    alpha = np.array([[0.5, 0.8], [0.9, 1.0]])
    cells = gkt.first_sonine(alpha, dimension=2)
    assert set(cells) == {"a2", "cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"}
    for name, values in cells.items():
        assert values.shape == (2, 2)
        for index in np.ndindex(2, 2):
            assert values[index] == gkt.first_sonine(float(alpha[index]), dimension=2)[name]
    assert cells["shear_viscosity"][1, 1] == pytest.approx(1.0)  # elastic: η* = 1
    assert cells["cooling_rate"][1, 1] == pytest.approx(0.0, abs=1e-15)


def test_enskog_first_sonine_pressure_and_dilute_limit():
    alpha = np.array([0.6, 0.8, 0.95])
    phi = 0.25
    dense = gkt.enskog_first_sonine(alpha, phi)
    chi = (1 - phi / 2) / (1 - phi) ** 3  # Carnahan-Starling
    np.testing.assert_allclose(dense["pressure"], 1 + 2 * (1 + alpha) * phi * chi, rtol=1e-14)  # theory.md (15.5)
    dilute = gkt.enskog_first_sonine(alpha, 0.0)
    plain = gkt.first_sonine(alpha)
    for name in ("a2", "cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"):
        np.testing.assert_allclose(dilute[name], plain[name], rtol=1e-12, atol=1e-15, err_msg=name)
    given = gkt.enskog_first_sonine(alpha, phi, chi=chi, phi_dchi=phi * (2.5 - phi) / (1 - phi) ** 4)
    for name in dense:
        np.testing.assert_allclose(given[name], dense[name], rtol=1e-13, err_msg=name)


def test_enskog_first_sonine_broadcasts_alpha_against_phi():
    alpha = np.linspace(0.5, 1.0, 3)[:, None]
    phi = np.array([0.0, 0.1, 0.3, 0.5])[None, :]
    grid = gkt.enskog_first_sonine(alpha, phi)
    assert grid["shear_viscosity"].shape == (3, 4)
    for j, p in enumerate(phi[0]):
        np.testing.assert_array_equal(grid["shear_viscosity"][:, j], gkt.enskog_first_sonine(alpha[:, 0], p)["shear_viscosity"])


def test_per_cell_errors():
    with pytest.raises(ValueError, match=r"^alpha: must be a number in \(0, 1\], got 1\.5$"):
        gkt.first_sonine([0.5, 1.5])
    with pytest.raises(ValueError, match="^dimension: must be 2 or 3, got 4$"):
        gkt.first_sonine(0.5, dimension=4)
    with pytest.raises(ValueError, match=r"^packing_fraction: must be a number in \[0, 0.5\] for dimension = 3, got 0.6$"):
        gkt.enskog_first_sonine(0.9, 0.6)
    with pytest.raises(ValueError, match=r"^packing_fraction: must be a number in \[0, 0.5\] for dimension = 3, got nan$"):
        gkt.enskog_first_sonine(0.9, math.nan)
    with pytest.raises(ValueError, match="^chi: give both chi and phi_dchi"):
        gkt.enskog_first_sonine(0.9, 0.1, chi=1.2)
    with pytest.raises(ValueError, match="^pair_correlation: unknown"):
        gkt.enskog_first_sonine(0.9, 0.1, pair_correlation="percus-yevick")
    with pytest.raises(ValueError):
        gkt.enskog_first_sonine([0.8, 0.9], [0.1, 0.2, 0.3])


def test_per_cell_calls_from_threads_agree():
    """Threads calling the per-cell loops at once (the GIL released inside) get the serial answers."""
    alphas = [np.linspace(0.2 + 0.01 * k, 1.0, 20000) for k in range(4)]
    serial = [gkt.first_sonine(a)["thermal_conductivity"] for a in alphas]
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        threaded = list(pool.map(lambda a: gkt.first_sonine(a)["thermal_conductivity"], alphas))
    for s, t in zip(serial, threaded):
        np.testing.assert_array_equal(s, t)


def test_version_is_the_programs():
    code, out, _ = run_cli("--version")
    assert code == 0
    assert out.strip() == f"gkt {gkt.__version__}"


def test_binary_table_at_a_node_equals_the_mixture_table():
    """At a Chebyshev node (x_1 = 1/2 of 5) the interpolated binary equals the solved mixture: T_i/T
    directly (the Navier-Stokes solver's Maxwellian HCS), η through η0(m̄, σ̄, T) = (5/(16 σ̄²)) √(m̄ T/π)
    (docs/conventions.md, 3D)."""
    table = gkt.BinaryTransportTable((1, 3), (1, 1.5), 0.8, order=1, nodes=5)
    assert 0 < table.interpolation_error < 0.1  # measured between 5 nodes: coarse
    assert table.validation_error <= table.interpolation_error
    cost = table.build_cost
    assert cost["intervals"] == 1 and cost["solves"] >= 5 + 4 and cost["seconds"] > 0
    n, temperature = np.array([1.0, 0.2]), np.array([1.0, 4.0])
    cells = table.evaluate(0.5, n, temperature)
    solved = gkt.table({"model": "mixture", "alpha": 0.8, "order": 1, "hcs": "maxwellian",
                        "coefficients": ["temperature_ratio_1", "temperature_ratio_2", "shear_viscosity"],
                        "species": [{"mass": 1, "diameter": 1, "fraction": 0.5}, {"mass": 3, "diameter": 1.5, "fraction": 0.5}]})
    for i in (1, 2):
        np.testing.assert_allclose(cells[f"temperature_ratio_{i}"], solved[f"temperature_ratio_{i}"][0], rtol=1e-10)
    eta0 = 5 / (16 * 1.25**2) * np.sqrt(2.0 * temperature / np.pi)
    np.testing.assert_allclose(cells["shear_viscosity"] / eta0, solved["shear_viscosity"][0], rtol=1e-10)
    assert np.all(cells["bulk_viscosity"] == 0)  # a dilute table
    np.testing.assert_array_equal(cells["pressure"], n * temperature)


def test_binary_table_shapes_and_errors():
    table = gkt.BinaryTransportTable((1, 2), (1, 1), [[0.9, 0.8], [0.8, 0.7]], order=1, nodes=5,
                                     max_packing_fraction=0.2, packing_nodes=4)
    x = np.linspace(0, 1, 6)[:, None]
    cells = table.evaluate(x, np.array([0.01, 0.1]), 1.0)
    assert cells["mutual_diffusion_1_2"].shape == (6, 2)
    assert len(cells) == 18
    assert np.all(np.isnan(table.evaluate(0.5, 10.0, 1.0)["shear_viscosity"]))  # phi beyond the table's 0.2
    with pytest.raises(ValueError, match="^alpha: must be a number or a 2 x 2 restitution matrix$"):
        gkt.BinaryTransportTable((1, 2), (1, 1), [0.9, 0.8])
    with pytest.raises(ValueError, match="mass"):
        gkt.BinaryTransportTable((0, 2), (1, 1), 0.9)
    with pytest.raises(ValueError, match="alpha"):
        gkt.BinaryTransportTable((1, 2), (1, 1), [[0.9, 0.8], [0.7, 0.9]])
    with pytest.raises(ValueError, match="nodes"):
        gkt.BinaryTransportTable((1, 2), (1, 1), 0.9, nodes=2)
    with pytest.raises(ValueError, match=r"^tolerance: must be a number in \(0, 1\], got 0$"):
        gkt.BinaryTransportTable((1, 2), (1, 1), 0.9, tolerance=0)


def test_binary_table_refuses_a_pole_of_the_truncated_solution():
    """Mass ratio 10 at order 1: the coefficients have a pole at x_1 ≈ 0.970 (theory.md §17.8); the
    table is refused with the library's one-line message naming the x_1 interval, not built wrong."""
    with pytest.raises(ValueError, match=r"^tolerance: the interpolation error .* on x_1 in \[0\.96"):
        gkt.BinaryTransportTable((1, 10), (1, 1), 0.8, order=1, nodes=8)
    # Below the pole the table builds and refuses compositions outside its range.
    table = gkt.BinaryTransportTable((1, 10), (1, 1), 0.8, order=1, nodes=8, fraction_range=(0, 0.9))
    assert table.interpolation_error <= 1e-3
    with pytest.raises(ValueError, match=r"^fraction_1: must be a number in \[0, 0\.9\] \(the table's fraction_range\), got 0\.95$"):
        table.evaluate(0.95, 1.0, 1.0)


# The dilute ternary of tests/test_ternary_transport_table.cpp: three unequal species and a full
# restitution matrix, tabulated cheaply (5 x 5 starting nodes, tolerance 5e-2: about a second).
TERNARY_MASS, TERNARY_DIAMETER = (1, 2, 3.5), (1, 1.3, 0.8)
TERNARY_ALPHA = [[0.9, 0.85, 0.75], [0.85, 0.8, 0.8], [0.75, 0.8, 0.7]]
TERNARY_TOLERANCE = 5e-2


@pytest.fixture(scope="module")
def ternary_table():
    return gkt.TernaryTransportTable(TERNARY_MASS, TERNARY_DIAMETER, TERNARY_ALPHA, order=1, nodes=5,
                                     tolerance=TERNARY_TOLERANCE)


def ternary_solve(x1, x2, coefficients):
    """Returns the mixture model's columns (gkt table, order 1, hcs = "maxwellian": the expansion the
    table solves) of the ternary at (x_1, x_2), one row."""
    fractions = (x1, x2, 1 - x1 - x2)
    return gkt.table({"model": "mixture", "alpha": TERNARY_ALPHA, "order": 1, "hcs": "maxwellian",
                      "coefficients": coefficients,
                      "species": [{"mass": m, "diameter": s, "fraction": x}
                                  for m, s, x in zip(TERNARY_MASS, TERNARY_DIAMETER, fractions)]})


def ternary_scales(x1, x2, n, temperature):
    """Returns {column: the physical scale of its reduced value} for the reference gas of
    m̄ = Σ x_i m_i, σ̄ = Σ x_i σ_i (gkt/transport/common/reference_gas.hpp, 3D, k_B = 1):
    η0 = (5/(16 σ̄²)) √(m̄ T/π), κ0 = (15/4) η0/m̄, D0 = (3/(8 √π)) √(T/m̄)/(n σ̄²), ν0 = nT/η0;
    D_ij scales as n D0, D^T_i and D^p_i as D0, D''_j as κ0/T, T_i/T as 1."""
    fractions = np.array([x1, x2, 1 - x1 - x2])
    mbar, sbar = fractions @ np.array(TERNARY_MASS, float), fractions @ np.array(TERNARY_DIAMETER, float)
    eta0 = 5 / (16 * sbar**2) * np.sqrt(mbar * temperature / np.pi)
    kappa0 = 15 / 4 * eta0 / mbar
    d0 = 3 / (8 * np.sqrt(np.pi)) * np.sqrt(temperature / mbar) / (n * sbar**2)
    scales = {"cooling_rate": n * temperature / eta0, "shear_viscosity": eta0, "thermal_conductivity": kappa0}
    for i in (1, 2, 3):
        scales[f"temperature_ratio_{i}"] = np.ones_like(eta0)
        scales[f"thermal_diffusion_{i}"] = scales[f"pressure_diffusion_{i}"] = d0
        scales[f"dufour_{i}"] = kappa0 / temperature
        for j in (1, 2, 3):
            scales[f"mutual_diffusion_{i}_{j}"] = n * d0
    return scales


def test_ternary_table_at_a_node_equals_the_mixture_table(ternary_table):
    """At a node of the Duffy square (u = v = 1/2: x_1 = 1/2, x_2 = 1/4, kept by every refinement
    and split) the interpolated ternary equals the solved mixture column by column (the names map to
    the right coefficients), through the reference gas of (m̄, σ̄) (rtol 1e-10: the reduction and the
    product by the scales round differently; zeros to 1e-12 of the scale)."""
    assert 0 < ternary_table.interpolation_error <= TERNARY_TOLERANCE
    assert ternary_table.validation_error <= ternary_table.interpolation_error
    cost = ternary_table.build_cost
    assert cost["pieces"] >= 1 and cost["nodes_per_axis"] >= 5 and cost["seconds"] > 0
    assert cost["solves"] >= 25 + 16  # nodes and midpoints at least
    n, temperature = np.array([1.0, 0.2]), np.array([1.0, 4.0])
    cells = ternary_table.evaluate(0.5, 0.25, n, temperature)
    scales = ternary_scales(0.5, 0.25, n, temperature)
    assert sorted(cells) == sorted([*scales, "pressure", "bulk_viscosity", "cooling_rate_first_order"])
    assert np.all(cells["bulk_viscosity"] == 0) and np.all(cells["cooling_rate_first_order"] == 0)  # dilute
    solved = ternary_solve(0.5, 0.25, list(scales))
    for name, scale in scales.items():
        np.testing.assert_allclose(cells[name] / scale, solved[name][0], rtol=1e-10, atol=1e-12, err_msg=name)
    assert np.any(np.abs(solved["pressure_diffusion_1"]) > 1e-3)  # the columns compared are not all zero
    np.testing.assert_array_equal(cells["pressure"], n * temperature)


def test_ternary_table_off_the_nodes_agrees_with_direct_solves(ternary_table):
    """Off the nodes the table agrees with direct solves within the tolerance it was built for
    (relative to max(1, |value|) of the reduced value, as the table measures its error), and is an
    interpolation there, not a lookup."""
    worst = 0.0
    for x1, x2 in ((0.21, 0.44), (0.05, 0.9), (0.63, 0.1)):
        n, temperature = 1.7, 0.6
        scales = ternary_scales(x1, x2, n, temperature)
        solved = ternary_solve(x1, x2, list(scales))
        cells = ternary_table.evaluate(x1, x2, n, temperature)
        for name, scale in scales.items():
            exact = solved[name][0]
            worst = max(worst, abs(cells[name] / scale - exact) / max(1.0, abs(exact)))
    assert 0 < worst <= TERNARY_TOLERANCE


def test_ternary_table_arrays_equal_single_calls_and_the_cpp_batch(ternary_table):
    """Broadcast arrays give, cell by cell, the same bits as single-state calls: both are
    gkt::evaluate of gkt/cell.hpp, which the C API's test (tests/c_api/test_c_api_ternary.cpp) shows
    equal bit for bit to TernaryTransportTable::evaluate and gkt_ternary_table_evaluate."""
    x1 = np.array([0.21, 0.05, 0.0, 1.0, 0.0])[:, None]
    x2 = np.array([0.44, 0.9, 0.0, 0.0, 1.0])[:, None]
    n, temperature = np.array([2.0, 0.3]), 1.5
    cells = ternary_table.evaluate(x1, x2, n, temperature)
    assert cells["mutual_diffusion_3_2"].shape == (5, 2)
    for r in range(5):
        for c in range(2):
            single = ternary_table.evaluate(x1[r, 0], x2[r, 0], n[c], temperature)
            for name, column in cells.items():
                assert column[r, c] == single[name][()], (name, r, c)
    assert np.all(np.isfinite(cells["shear_viscosity"]))  # the vertices are states too


def test_ternary_table_errors():
    with pytest.raises(ValueError, match="^alpha: must be a number or a 3 x 3 restitution matrix$"):
        gkt.TernaryTransportTable(TERNARY_MASS, TERNARY_DIAMETER, [[0.9, 0.8], [0.8, 0.7]])
    with pytest.raises(ValueError, match="^alpha_1_2: the restitution matrix must be symmetric, got 0.85 and 0.8$"):
        gkt.TernaryTransportTable(TERNARY_MASS, TERNARY_DIAMETER, [[0.9, 0.85, 0.75], [0.8, 0.8, 0.8], [0.75, 0.8, 0.7]])
    with pytest.raises(ValueError, match="mass"):
        gkt.TernaryTransportTable((1, 0, 2), TERNARY_DIAMETER, 0.9)
    with pytest.raises(ValueError, match=r"^nodes: must be an integer in \[3, 33\], got 2$"):
        gkt.TernaryTransportTable(TERNARY_MASS, TERNARY_DIAMETER, 0.9, nodes=2)
    with pytest.raises(ValueError, match=r"^max_nodes: must be an integer in \[nodes, 33\]"):
        gkt.TernaryTransportTable(TERNARY_MASS, TERNARY_DIAMETER, 0.9, nodes=9, max_nodes=8)
    with pytest.raises(ValueError, match=r"^tolerance: must be a number in \(0, 1\], got 0$"):
        gkt.TernaryTransportTable(TERNARY_MASS, TERNARY_DIAMETER, 0.9, tolerance=0)
    table = gkt.TernaryTransportTable(TERNARY_MASS, TERNARY_DIAMETER, 0.9, order=1, nodes=3, tolerance=1.0)
    with pytest.raises(ValueError, match=r"^fraction_2: must be a number in \[0, 1 - fraction_1\], got 0\.5$"):
        table.evaluate(0.6, 0.5, 1.0, 1.0)
    with pytest.raises(ValueError, match="^fraction_1"):
        table.evaluate(-0.1, 0.5, 1.0, 1.0)
    with pytest.raises(ValueError, match="^number_density"):
        table.evaluate(0.1, 0.5, [1.0, 0.0], 1.0)
    with pytest.raises(ValueError, match="^temperature"):
        table.evaluate(0.1, 0.5, 1.0, np.nan)


def test_ternary_table_refuses_a_pole_of_the_truncated_solution():
    """Species 2 ten times heavier than 1 and 3 at order 1: the binary's pole runs along the triangle
    (theory.md §17.8); the table is refused with the library's one-line message naming the region."""
    pattern = r"^tolerance: the interpolation error .* on x_1 in \[0\.97.*, x_2/\(1 - x_1\) in \["
    with pytest.raises(ValueError, match=pattern) as refused:  # 3 x 3 nodes, no refinement: cheap
        gkt.TernaryTransportTable((1, 10, 1), (1, 1, 1), 0.8, order=1, nodes=3, tolerance=5e-2, max_nodes=3)
    assert "\n" not in str(refused.value)


# The dense ternary of tests/test_ternary_transport_table.cpp (DenseEqualsDirectSolves): three similar
# species, 3 nodes per axis and in phi in [0, 0.1], no refinement, tolerance 5e-2 (a few seconds).
DENSE_MASS, DENSE_DIAMETER = (1, 1.2, 1.4), (1, 1.1, 0.95)
DENSE_ALPHA = [[0.9, 0.85, 0.8], [0.85, 0.8, 0.8], [0.8, 0.8, 0.85]]
DENSE_PHI_MAX = 0.1


@pytest.fixture(scope="module")
def dense_ternary_table():
    return gkt.TernaryTransportTable(DENSE_MASS, DENSE_DIAMETER, DENSE_ALPHA, order=1, nodes=3, max_nodes=3,
                                     tolerance=TERNARY_TOLERANCE, max_packing_fraction=DENSE_PHI_MAX,
                                     packing_nodes=3)


def test_dense_ternary_table_agrees_with_direct_dense_solves(dense_ternary_table):
    """Off the nodes (x_1, x_2, phi) = (0.21, 0.44, 0.07) the dense table's physical set, divided by the
    reference gas of (m̄, σ̄) at n, T (p by nT, κ_b by η0, ζ_U by 1), agrees with the mixture model's
    columns at that packing_fraction within the tolerance the table was built for; above phi_max every
    value is nan (the per-cell contract of gkt::evaluate)."""
    table = dense_ternary_table
    assert 0 < table.interpolation_error <= TERNARY_TOLERANCE
    assert table.build_cost["packing_nodes"] >= 3
    x1, x2, phi, temperature = 0.21, 0.44, 0.07, 0.8
    fractions = np.array([x1, x2, 1 - x1 - x2])
    mbar, sbar = fractions @ np.array(DENSE_MASS, float), fractions @ np.array(DENSE_DIAMETER, float)
    n = phi / (np.pi / 6 * (fractions @ np.array(DENSE_DIAMETER, float) ** 3))
    eta0 = 5 / (16 * sbar**2) * np.sqrt(mbar * temperature / np.pi)
    kappa0 = 15 / 4 * eta0 / mbar
    scales = {"shear_viscosity": eta0, "thermal_conductivity": kappa0, "bulk_viscosity": eta0,
              "cooling_rate_first_order": 1.0, "pressure": n * temperature, "cooling_rate": n * temperature / eta0}
    solved = gkt.table({"model": "mixture", "alpha": DENSE_ALPHA, "order": 1, "hcs": "maxwellian",
                        "packing_fraction": phi, "coefficients": list(scales),
                        "species": [{"mass": m, "diameter": s, "fraction": x}
                                    for m, s, x in zip(DENSE_MASS, DENSE_DIAMETER, fractions)]})
    cells = table.evaluate(x1, x2, n, temperature)
    for name, scale in scales.items():
        exact = solved[name][0]
        assert abs(cells[name] / scale - exact) <= TERNARY_TOLERANCE * max(1.0, abs(exact)), name
    assert solved["pressure"][0] > 1.1 and solved["bulk_viscosity"][0] > 0  # dense values, not dilute ones
    beyond = table.evaluate(x1, x2, 2 * n, temperature)
    assert all(np.isnan(column[()]) for column in beyond.values())


def test_dense_ternary_table_refusals():
    """Bad phi_max and packing_nodes name the field (a tolerance the table cannot meet is refused by the
    same constructor: test_ternary_table_refuses_a_pole_of_the_truncated_solution; a dense refusal splits
    for ~20 s before it gives up, too slow for this suite)."""
    with pytest.raises(ValueError, match=r"^max_packing_fraction: must be a number in \[0, 0\.5\) for dimension = 3"):
        gkt.TernaryTransportTable(DENSE_MASS, DENSE_DIAMETER, 0.9, max_packing_fraction=0.6)
    with pytest.raises(ValueError, match=r"^max_packing_fraction: must be a number in \[0, 0\.5\) for dimension = 3"):
        gkt.TernaryTransportTable(DENSE_MASS, DENSE_DIAMETER, 0.9, max_packing_fraction=-0.1)
    with pytest.raises(ValueError, match=r"^packing_nodes: must be an integer in \[3, 33\], got 2$"):
        gkt.TernaryTransportTable(DENSE_MASS, DENSE_DIAMETER, 0.9, max_packing_fraction=0.1, packing_nodes=2)


def test_binary_table_about_the_cumulant_hcs_is_the_one_component_gas():
    """Identical species about the nonlinear HCS with a_2 (reference="nonlinear", hcs_order=2, docs/theory.md
    section 17.14): the binary table's eta, lambda, sum_j D''_j and zeta, reduced by the reference gas, equal the
    smooth-inelastic model at order 1 (which keeps a_2 in f0) to round-off; the default Maxwellian reference does
    not (lambda off by > 1e-3). A bad reference or hcs_order is refused naming the field."""
    alpha, x1, n, temperature = 0.7, 0.3, 1.0, 1.0
    one = gkt.table({"model": "smooth-inelastic", "alpha": alpha, "order": 1,
                     "coefficients": ["shear_viscosity", "thermal_conductivity", "density_heat_coefficient",
                                      "cooling_rate"]})
    eta0 = 5 / 16 * np.sqrt(temperature / np.pi)
    kappa0 = 15 / 4 * eta0
    cumulant = gkt.BinaryTransportTable((1, 1), (1, 1), alpha, order=1, nodes=3, tolerance=1e-9,
                                        reference="nonlinear", hcs_order=2).evaluate(x1, n, temperature)
    np.testing.assert_allclose(cumulant["shear_viscosity"] / eta0, one["shear_viscosity"][0], rtol=1e-12)
    np.testing.assert_allclose(cumulant["thermal_conductivity"] / kappa0, one["thermal_conductivity"][0], rtol=1e-12)
    np.testing.assert_allclose((cumulant["dufour_1"] + cumulant["dufour_2"]) * temperature / kappa0,
                               one["density_heat_coefficient"][0], rtol=1e-12)
    np.testing.assert_allclose(cumulant["cooling_rate"] * eta0 / (n * temperature), one["cooling_rate"][0], rtol=1e-12)
    maxwellian = gkt.BinaryTransportTable((1, 1), (1, 1), alpha, order=1, nodes=3, tolerance=1e-9)
    assert abs(maxwellian.evaluate(x1, n, temperature)["thermal_conductivity"] / kappa0
               / one["thermal_conductivity"][0] - 1) > 1e-3
    with pytest.raises(ValueError, match=r'^reference: must be "maxwellian", "linear" or "nonlinear", got "hcs"$'):
        gkt.BinaryTransportTable((1, 1), (1, 1), alpha, reference="hcs")
    with pytest.raises(ValueError, match=r"^hcs_order: must be an integer in \[2, 6\]"):
        gkt.TernaryTransportTable((1, 2, 3), (1, 1, 1), alpha, reference="linear", hcs_order=7)
