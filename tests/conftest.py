"""Shared test settings: a hypothesis profile that keeps the suite fast on two cores, the
``slow`` mark on the tests that take a second or more (``pytest -m "not slow"`` runs
the rest; tests/README.md says which and why), and what collection built moved out of
the garbage collector's way."""

import gc
import os

from hypothesis import HealthCheck, settings

settings.register_profile("ci", max_examples=50, deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))

import pytest

#: Tests that take a second or more on a quiet machine: they integrate equations of
#: motion numerically, derive with sympy, lay out math in a browser or generate and
#: grade a whole exam. Listed here (file, test function) so that their files stay as
#: they are; a name that no longer exists marks nothing.
SLOW = {
    ("test_mechanics_ch4_lagrange.py", "test_double_pendulum_equations_agree_with_newton_euler"),
    ("test_mechanics_ch4_lagrange.py",
     "test_small_oscillations_about_the_stable_equilibrium_have_the_linearized_period"),
    ("test_mechanics_ch4_lagrange.py",
     "test_mass_matrix_of_the_double_pendulum_is_the_hessian_of_T_written_out_by_hand"),
    ("test_mechanics_ch4_multi_dof.py",
     "test_forced_steady_state_amplitudes_match_numerical_integration"),
    ("test_mechanics_ch4_multi_dof.py", "test_modal_superposition_equals_direct_integration"),
    ("test_mechanics_ch4_vibrations.py",
     "test_forced_steady_state_matches_numerical_integration_after_transients"),
    ("test_mechanics_ch3_rotation.py",
     "test_rotation_about_intermediate_axis_is_unstable_and_about_extreme_axes_stable"),
    ("test_mechanics_ch3_rotation.py", "test_motion_solved_in_rotating_frame_agrees_with_inertial_frame"),
    ("test_mechanics_ch3_rotation.py",
     "test_torque_free_euler_equations_conserve_energy_and_angular_momentum_magnitude"),
    ("test_mechanics_ch3_rotation.py", "test_off_steady_precession_rate_makes_the_top_nod"),
    ("test_mechanics_ch3_rotation.py", "test_steady_precession_keeps_the_tilt_constant_in_simulation"),
    ("test_mechanics_ch1_kinematics.py",
     "test_polar_components_equal_projections_of_the_differentiated_cartesian_position"),
    ("test_mechanics_ch2_systems.py", "test_centre_of_mass_moves_as_particle_under_total_external_force"),
    ("test_mechanics_ch1_angular_momentum.py", "test_small_angle_pendulum_period_matches_integration"),
    ("test_exam_grading.py", "test_the_class_gets_exactly_the_expected_gradebook"),
    ("test_exam_generate.py", "test_a_second_run_writes_byte_identical_files"),
    ("test_render_moodle.py", "test_dynagrade_moodle_writes_the_pool_asked_for"),
    ("test_render_moodle.py",
     "test_dynagrade_moodle_names_an_unknown_exercise_without_a_traceback"),
    ("test_render_math.py", "test_a_generated_html_sheet_lays_out_its_math_and_figures_in_chromium"),
    ("test_render_math.py", "test_the_whole_subset_is_laid_out_as_math_in_chromium"),
    ("test_grading_parser.py", "test_random_trees_round_trip_through_print_and_parse"),
}


def pytest_configure(config):
    config.addinivalue_line("markers", "slow: takes a second or more (see tests/README.md)")


def pytest_collection_modifyitems(config, items):
    for item in items:
        if (item.path.name, item.originalname) in SLOW:
            item.add_marker(pytest.mark.slow)


@pytest.hookimpl(trylast=True)
def pytest_collectreport():
    """Freeze what collecting a module built: its code, the libraries it imports and the
    objects behind its test items, all alive until the process ends. The garbage
    collector's full passes -- some while collecting, pytest's own at the end of a
    session, the interpreter's at exit (together 0.3 s of a ``--collect-only``) and
    those during the run -- then stop walking them again, as after
    :func:`dynagrade.grading.prepare` they stop walking sympy and pint. Garbage made
    during the tests is collected as before."""
    gc.freeze()


@pytest.hookimpl(trylast=True)
def pytest_collection_finish():
    """Freeze, as each module's, what the plugins' last look at the items built."""
    gc.freeze()


@pytest.fixture(scope="session")
def bank():
    """The shipped exercise bank."""
    from dynagrade.exercise import open_bank

    return open_bank()


#: a three-exercise exam spec shared by the exam tests (three figures, one value set)
EXAM_TOML = """\
id = "dynamics-test-exam"
title = "Dynamics: test exam"
date = 2025-04-14
instructions = "Answer every part."

[[exercise]]
id = "projectile-range"
points = 6

[[exercise]]
id = "sliding-up-a-slope"
points = 6

[[exercise]]
id = "car-in-a-looping"
points = 8
[exercise.set]
g = 9.81
"""


@pytest.fixture(scope="session")
def exam_toml():
    """:data:`EXAM_TOML`."""
    return EXAM_TOML
