"""The equality rows of every jointed structure solved together, each (sub-)step.

Sequential soft rows (Box2D v3) transmit a load along a chain of joints only
partly per pass, so long chains stretch and cantilevers sag (a weld cantilever
of ten 1 x 0.25 m boxes: 175 cm in Box2D v3).  Here the equality rows of all
joints are one linear system per pass,
    (J M^-1 J^T + Gamma) dlam = -(J v + bias + Gamma lam),
assembled over the body rows and solved exactly by a sparse LDL^T
factorisation (Davis, "Direct Methods for Sparse Linear Systems", SIAM 2006,
ch. 4: the up-looking LDL with its elimination tree).  Joints are ordered by
minimum degree (Tinney & Walker 1967) on the graph of joints that share a
moving body; a tree of joints (chains, ragdolls, cantilevers, cars) then
factorises without fill in linear time, as Baraff's method does ("Linear-time
dynamics using Lagrange multipliers", SIGGRAPH 1996), and a few loops (a
walker's linkage) cost a little fill.  A structure whose factor would fill
beyond a budget (a cloth-like grid) keeps the sequential rows; a structure of
one joint is solved as its own dense block, with the system's arithmetic.

- ``topology``: which rows, their order, the pattern, the symbolic factor (Python, on change);
- ``ldl``: the numeric factorisation and solve (kernels);
- ``solve``: assembly from the joints' rows and the velocity and position passes;
- ``block``: the passes for a structure of one joint.
"""
