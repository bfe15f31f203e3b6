"""The mechanics core: one module per principle of the course, SI units throughout.

Each function returns one physical quantity and cites the relation of the lecture notes it
implements.  Nothing here imports from the rest of dynagrade.

Taxonomy
    The modules of this package are the core, one per principle or topic (kinematics,
    particle, energy, angular_momentum, collisions, systems, rigid bodies, vibrations,
    continua, ...).  Relations that belong to one worked example of the notes live in
    :mod:`dynagrade.mechanics.examples`, which imports the core and is never imported by it.
    Public function names are unique across the whole package and say whose quantity they
    compute (``particle_kinetic_energy``, ``rigid_body_kinetic_energy``,
    ``system_kinetic_energy``).

Argument convention
    A physical quantity is named by its symbol in the notes, spelled in ASCII: ``m`` a mass
    (``M`` the total mass of a system or a mass matrix), ``R`` a radius, ``L`` or ``l`` a
    length as the notes write it, ``h`` a height, ``g`` gravity, ``k`` a stiffness, ``c`` a
    damping coefficient, ``t`` time, ``v`` a velocity, ``omega`` an angular velocity,
    ``phi``/``theta``/``alpha`` angles, ``rhoA`` a mass per length, ``EI`` a bending
    stiffness.  A trailing ``0`` marks an initial value (``v0``, ``x0``, ``omega0``) and
    ``dot`` a time derivative (``phidot``).  The spelled-out synonyms of these symbols
    (``mass``, ``radius``, ``height``, ``length``, ``angle``, ``initial_speed``, ...) are
    not used; descriptive snake_case names are kept for quantities the notes give no
    single symbol (``moment_centre`` for I_C, ``lever_arm``, ``exhaust_speed``), for
    plural inputs (``masses``, ``positions``) and for arguments that are functions
    (``force``, ``acceleration``, ``path``).  tests/test_mechanics_structure.py checks
    every public signature against this list.

Sign conventions
    Where a result has a free sign, the function fixes it and says so: a mode shape of
    :func:`multi_dof.mode_shapes` has its first non-zero entry positive (and
    Phi^T M Phi = I); tests/test_mechanics_pins.py holds the convention.

Types
    Every public function carries type hints.  A quantity a function computes with is a
    ``Quantity`` of :mod:`dynagrade.mechanics._common` (a float or a numpy array, so one
    call evaluates a whole grid of values) and results are returned as one; an argument
    the function first converts to an array (a vector, a list of masses or times) is
    ``ArrayLike`` and may also be a list or a tuple.

Imports
    Importing a core module does not import scipy: the functions that integrate, solve or
    diagonalise import it when called.
"""
