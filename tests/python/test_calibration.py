# Tissue calibration through the bindings: the law by hand (Hertz), a noise-free round trip
# of modulus and depth, and bad arguments as ergo.InputError naming the argument.
import math

import numpy as np
import pytest

import ergo


def test_half_space_is_hertz_by_hand():
    # R = 5 mm, E = 50 kPa, nu = 0.5, delta = 1 mm: 4/3 E/(1 - nu^2) sqrt(R) delta^1.5.
    force = ergo.indentation_force(5e4, None, [0.001], indenter_radius=0.005, poisson_ratio=0.5)
    assert force[0] == pytest.approx(4 / 3 * 5e4 / 0.75 * math.sqrt(0.005) * 0.001 ** 1.5,
                                     rel=1e-12)


def test_a_curve_of_the_law_gives_back_its_modulus_and_depth():
    delta = np.linspace(0, 0.006, 31)
    force = ergo.indentation_force(4.5e4, 0.017, delta, indenter_radius=0.01)
    fit = ergo.fit_indentation(delta, force, indenter_radius=0.01, fit_depth=True, depth=0.04)
    assert fit["converged"], fit["summary"]
    assert fit["youngs_modulus"] == pytest.approx(4.5e4, rel=1e-6)
    assert fit["depth"] == pytest.approx(0.017, rel=1e-6)
    assert fit["readings"] == 30
    half = ergo.fit_indentation(delta, force, indenter_radius=0.01)
    assert half["depth"] is None
    assert half["youngs_modulus"] > 1.2 * 4.5e4  # a half-space reads the layer too stiff


def test_a_logger_zero_before_contact_is_found():
    logged = np.linspace(-0.0005, 0.006, 41)
    force = [0.0 if d <= 0.0004 else f for d, f in
             zip(logged, ergo.indentation_force(4.5e4, 0.017, np.maximum(logged - 0.0004, 0),
                                                indenter_radius=0.01))]
    fit = ergo.fit_indentation(logged, force, indenter_radius=0.01, fit_depth=True,
                               fit_contact_point=True)
    assert fit["converged"], fit["summary"]
    assert fit["contact_offset"] == pytest.approx(0.0004, abs=1e-8)
    assert fit["youngs_modulus"] == pytest.approx(4.5e4, rel=1e-5)


def test_bad_arguments_name_themselves():
    with pytest.raises(ergo.InputError, match="indenter_radius"):
        ergo.fit_indentation([0.001, 0.002], [0.1, 0.3], indenter_radius=0)
    with pytest.raises(ergo.InputError, match="layer_base"):
        ergo.fit_indentation([0.001, 0.002], [0.1, 0.3], indenter_radius=0.01,
                             layer_base="glued")
    with pytest.raises(ergo.InputError, match="force"):
        ergo.fit_indentation([0.001, 0.002], [0.1], indenter_radius=0.01)
    with pytest.raises(ergo.InputError, match="depth"):
        ergo.indentation_force(5e4, -1.0, [0.001], indenter_radius=0.01)
