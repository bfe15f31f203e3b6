"""Relations tied to one worked example of the lecture notes.

Each module here describes one example's set-up (the looping of Example 1.13, the block on
an inclined plane of Examples 1.8 and 1.15, the projectile of Example 1.9, the bead on a
spinning hoop of Section 4.2) and is built on the principle modules of
:mod:`dynagrade.mechanics`.  The core never imports this package;
tests/test_mechanics_taxonomy.py holds that.
"""
