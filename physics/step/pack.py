"""The step pack: every array one step reads or writes, behind one compiled-call argument.

Unboxing costs per array argument (about 150 ns each, docs/flat-step.md); a step over some
fifty arrays would spend several microseconds at the boundary alone.  A numba StructRef holds
references to the same numpy arrays (no copy) and crosses the boundary as one object (about
0.6 us whatever it holds), so the driver (driver.py) takes the pack and nothing else.

Fields a world may lack (the joint tables, the spring solve, the whole narrow phase) are None; the pack's numba
type then differs and the driver compiled for it contains none of that code, as optional.py
does for the kernels.  The Python side (one_call.py) builds a pack when the world's structure
changes and keeps it between steps.
"""
from __future__ import annotations

from numba import types
from numba.core import cgutils
from numba.experimental import structref
from numba.extending import intrinsic

from .._jit import kernel

#: the fields, in constructor order
FIELDS = (
    # the step context, the mode's parameters, the driver's int state (S_* slots, driver.py),
    # its float inputs (D_* slots), its cycle stamps, the energy guard's state (energy_bound.py)
    "ctx", "par", "S", "D", "T", "G",
    # the tables' flat arrays (store/flat.py): bodies, fixtures, vertices, springs
    "BF", "BI", "FF", "FI", "ghost", "wghost", "VF", "VI", "SF", "SI",
    # the two contact tables, this step's and the last (their roles swap every step: S_CPAR)
    "CAF", "CAI", "CApt", "CBF", "CBI", "CBpt",
    # broad-phase pairs, the body pairs joints exclude from colliding, the pairs' keys and order
    # and the narrow phase's manifold scratch (collision/narrowphase/kernel.py: collide_with)
    "pairs", "exclude", "pkeys", "porder", "mscratch",
    # the checkpoint (checkpoint.py) and the push-out allowance's scratch (push_out.py), the guard's
    # sums before and after (energy_sums.py)
    "X", "Q", "V", "W", "bad", "why", "cluster", "start", "end",
    # the touching sets and their spares (contact_events.py; roles swap with S_EPAR)
    "EK0", "EK1", "EB0", "EB1", "EA0", "EA1",
    # islands (islands.py) and the joints' links for them
    "parent", "min_t", "label", "links",
    # soft_step's contact scratch, body rows and start velocities
    "R", "SB", "V0",
    # joints (None without): table, scratch, global system, the joined bodies' kinds
    "JF", "JI", "JW", "JS", "kinds",
    # the springs' float array again when the world has springs, for the solve (None without)
    "SS",
    # the narrow phase's whole kernel (1) or only its lean one (None: collision/narrowphase/kernel.py)
    "full",
    # the sweep broad phase's scratch (broadphase/sweep.py: sweep_pairs' arrays from ``state`` to
    # ``head``, the world's own, so its kept order is this world's; empty under brute force)
    "sweep",
    # the coloured layout's scratch (solvers/soft_step/layout.py: ColouredScratch.pack_fields), None
    # in the rows layout
    "wide",
    # 1 in a world large enough to split its loops between threads, None in the serial build
    # (physics/threads.py: the driver for None contains no parallel loop)
    "split",
    # the step's lists and their scratch (active.Active.fields): moving bodies, their fixtures,
    # the sleepers, the checkpoint's rows and their marks (checkpoint.py), the resting boxes'
    # index, the islands' member cycles and a sort's scratch
    "active",
)


@structref.register
class StepPackType(types.StructRef):
    def preprocess_fields(self, fields):
        return tuple((name, types.unliteral(t)) for name, t in fields)


class StepPack(structref.StructRefProxy):
    """The Python handle of a pack (build it with ``StepPack(*values)`` in FIELDS order)."""


structref.define_proxy(StepPack, StepPackType, list(FIELDS))


@kernel(entry=True, runtime=True)
def new_pack(*values):
    """A pack of ``values`` (FIELDS order).  ``StepPack(...)`` would compile numba's own
    constructor for each new pack type in every process (it is not cached); this one is."""
    return StepPack(*values)


def pack_signature(values) -> tuple:
    """The driver's argument types for a pack of ``values`` (FIELDS order), without building it:
    what ``soft_world_step.overloads`` is keyed by once the driver is compiled for such a pack."""
    from numba import typeof
    return (StepPackType([(name, typeof(v)) for name, v in zip(FIELDS, values)]),)


@intrinsic
def call_with_fields(typingctx, fn, pack):
    """``fn(*fields)``: the compiled function ``fn`` called with the pack's fields in FIELDS order,
    as they lie in the pack.  ``P.x`` takes a reference to each array it reads and the caller
    drops it after the call; numba's pruning pass removes such pairs only within one block, and
    a call's error check splits the block, so a driver reading fifty arrays from its pack paid
    for a hundred atomic updates per step.  Here the caller lends the pack's arrays instead: the
    pack holds them for the whole call (built on numba's documented extension API: a StructRef's
    payload, a dispatcher's compiled function)."""
    if not isinstance(pack, StepPackType) or not isinstance(fn, types.Dispatcher):
        return None
    fields = dict(pack.field_dict)
    argtys = tuple(fields[name] for name in FIELDS)
    fsig = typingctx.resolve_function_type(fn, argtys, {})

    def codegen(context, builder, sig, args):
        ref = cgutils.create_struct_proxy(pack)(context, builder, value=args[1])
        payload = pack.get_data_type()
        ptr = context.nrt.meminfo_data(builder, ref.meminfo)
        ptr = builder.bitcast(ptr, context.data_model_manager[payload].get_value_type().as_pointer())
        data = cgutils.create_struct_proxy(payload)(context, builder, ref=ptr)
        impl = context.get_function(fn, fsig)
        return impl(builder, [getattr(data, name) for name in FIELDS])

    return fsig.return_type(fn, pack), codegen
