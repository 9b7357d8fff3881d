"""The seed report's modes: ``impulse``, ``penalty`` and ``hybrid``.

They move the bodies first (force generators integrated by explicit Euler,
symplectic Euler or RK4, automatically sub-stepped for stiff springs and
penalty contacts) and respond to contacts afterwards: impulses with
projection, penalty springs, or both.
"""
