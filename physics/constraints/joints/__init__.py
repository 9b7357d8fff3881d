"""Joint rows: one module per kind, the same verbs for all (docs/internals.md).

Every joint is up to seven scalar rows (store/joints.py: three equality rows,
a spring, a motor, a lower and an upper limit), each written per pass as a
Jacobian on the body rows (constraints/body_rows.py) by its kind's ``rows_*``
function.  What a kind knows is only its geometry; the verbs are shared:

- ``layout``    the prepared per-joint constants and the row fields;
- ``frame``     current arms and separation from the step-start frame and the
                bodies' displacement since (Box2D v3's deltaPosition/deltaRotation);
- ``rows``      the row algebra: speed, impulse, effective mass, the spring,
                motor and limit rows, the equality block of one joint;
- ``revolute``, ``prismatic``, ``weld``, ``distance``, ``wheel``: the geometry;
- ``motor``, ``mouse``: geometry and their own clamped solves;
- ``prepare``   once per step: frames, softness, clamps, which joints are on;
- ``dispatch``  warm start, solve (with bias; without: relax), store (readouts, breaking);
- ``system/``   the equality rows of a jointed structure solved together (sparse LDL^T);
- ``position``  non-linear Gauss-Seidel position correction (sequential_impulse, classic);
- ``sync``      body rows from and to the body table (modes whose contacts use the table);
- ``work``      the scratch arrays and their upkeep (Python).
"""
