"""A store table as compiled code sees it: its few 2-D arrays, its fields made on access.

A namedtuple of 20-26 column arrays is, to numba, 20-26 array structs passed by value: every
call between kernels copies some 200 machine words, and every kernel's IR is mostly that
plumbing (docs/flat-step.md measures it: 3x the compile time, 7x the run time of the same
kernels over one 2-D array).  A ``TableType`` value holds only the table's own arrays (``F``,
``I`` and the fields that are arrays of their own, store/table.py's ``Columns``), and
``T.x`` builds the column view ``F[:, c:c+2]`` where it is read: a few integer operations that
LLVM folds into the indexing.  The kernels' source does not change (``B.x[i, 0]`` reads as
before); only what crosses a call shrinks.

The Python side is a ``TableView`` class per table (``view_class``), whose attributes are the
same column arrays the namedtuple held, so Python code reads and writes the same memory.  numba
types an instance from its arrays (``typeof``) and unboxes only those; compiled code builds the
same type from the arrays with ``make_table`` (store/flat.py), so a kernel compiles once for
both callers.  A view whose columns are not one ``Columns`` layout (arrays made one by one)
holds each field as an array of its own: slower to pass, never wrong.

Built on numba's documented low-level extension API (a type, its data model, attribute typing
and lowering, typeof and unbox).
"""
from __future__ import annotations

import zlib

import numpy as np
from numba import types
from numba.core import cgutils
from numba.core.imputils import impl_ret_borrowed
from numba.core.typing.templates import AttributeTemplate
from numba.extending import infer_getattr, intrinsic, lower_getattr_generic, models, register_model
from numba.np.arrayobj import make_array, populate_array

from .table import separate

WHOLE = -1   # a field's ``col`` when the field is a source array itself


class SourcesType(types.Type):
    """A compact value over a few source arrays (a table here, a segments record in
    store/segments.py): ``tag`` names the layout, ``fields`` place each field in the sources,
    ``sources`` are the numba types of the arrays the value holds."""

    def __init__(self, tag: str, fields: tuple, sources: tuple, kind: str):
        self.tag = tag
        self.fields = fields
        self.sources = sources
        self.by_name = {f[0]: f for f in fields}
        # numba hashes an argument's type on every call from Python; the key nests some thirty
        # types, so its hash is computed once, from its text (the same in every process: the
        # hash travels with the type into numba's disk cache)
        self._hash = zlib.crc32(repr((tag, fields, sources)).encode())
        super().__init__(name=f"{tag}{kind}({', '.join(map(str, sources))})")

    @property
    def key(self):
        return self.tag, self.fields, self.sources

    def __hash__(self):
        return self._hash


class TableType(SourcesType):
    """``fields``: per field (name, source index, first column or WHOLE, width or 0 for a 1-D
    column, dtype); ``sources``: the numba types of the arrays the value holds."""

    def __init__(self, tag: str, fields: tuple, sources: tuple):
        super().__init__(tag, fields, sources, "Table")

    def field_type(self, name: str):
        _, src, col, width, dt = self.by_name[name]
        if col == WHOLE:
            return self.sources[src]
        return types.Array(dt, 1 if width == 0 else 2, "A")


@register_model(TableType)
class SourcesModel(models.StructModel):
    """The value is its source arrays, ``s0``, ``s1``, ... (store/segments.py's records too)."""

    def __init__(self, dmm, fe_type):
        super().__init__(dmm, fe_type, [(f"s{i}", t) for i, t in enumerate(fe_type.sources)])


@infer_getattr
class _TableAttributes(AttributeTemplate):
    key = TableType

    def generic_resolve(self, typ, attr):
        if attr in typ.by_name:
            return typ.field_type(attr)


@lower_getattr_generic(TableType)
def _field(context, builder, typ, value, attr):
    """The column view: data at column ``col`` of its source, the source's row stride, and for a
    C-ordered source (every Columns array) an inner stride of one item, a constant LLVM folds."""
    _, src, col, width, dt = typ.by_name[attr]
    sty = typ.sources[src]
    sval = getattr(cgutils.create_struct_proxy(typ)(context, builder, value=value), f"s{src}")
    if col == WHOLE:
        return impl_ret_borrowed(context, builder, sty, sval)
    base = make_array(sty)(context, builder, value=sval)
    rows = cgutils.unpack_tuple(builder, base.shape)[0]
    row_stride = cgutils.unpack_tuple(builder, base.strides)[0]
    intp = lambda k: context.get_constant(types.intp, k)
    item = intp(context.get_abi_sizeof(context.get_data_type(dt)))
    inner = item if sty.layout == "C" else cgutils.unpack_tuple(builder, base.strides)[1]
    data = cgutils.pointer_add(builder, base.data, builder.mul(inner, intp(col)))
    data = builder.bitcast(data, context.get_data_type(dt).as_pointer())
    resty = typ.field_type(attr)
    shape, strides = ([rows], [row_stride]) if width == 0 else ([rows, intp(width)], [row_stride, inner])
    out = make_array(resty)(context, builder)
    populate_array(out, data=data, shape=shape, strides=strides, itemsize=item, meminfo=base.meminfo)
    return impl_ret_borrowed(context, builder, resty, out._getvalue())


# -- the layouts -------------------------------------------------------------------------------
#: tag -> the table's field spec, for make_table
SPECS: dict[str, dict] = {}


def _dtype(dt) -> types.Type:
    """A field's element type as Columns stores it: floats float64, integers int64 (uint64 kept)."""
    dt = np.dtype(dt)
    if dt.kind == "f":
        return types.float64
    return types.uint64 if dt == np.uint64 else types.int64


def own(spec_entry) -> bool:
    """Whether a field is an array of its own: two or more dimensions per entry, or declared so
    (a third item "own": scratch with a row count of its own, e.g. per body in a joint table)."""
    return separate(spec_entry[0]) or spec_entry[2:] == ("own",)


def column_fields(spec: dict) -> tuple:
    """The ``fields`` of a table laid out as store/table.py's Columns: the float columns in ``F``,
    the integer columns in ``I``, each field of its own (``own``) a source of its own; sources
    numbered in that order, counting only those the table has (``sources_of``)."""
    kinds = [("X" if own(e) else "F" if np.dtype(e[1]).kind == "f" else "I") for e in spec.values()]
    order = [k for k in ("F", "I") if k in kinds]
    out, col, extra = [], {"F": 0, "I": 0}, len(order)
    for (name, (shape, dt, *_)), k in zip(spec.items(), kinds):
        if k == "X":
            out.append((name, extra, WHOLE, 0, _dtype(dt)))
            extra += 1
            continue
        w = int(np.prod(shape))
        out.append((name, order.index(k), col[k], 0 if not shape else w, _dtype(dt)))
        col[k] += w
    return tuple(out)


def sources_of(spec: dict) -> list[str]:
    """The names of a Columns table's sources in column_fields' numbering: "F", "I" (those the
    table has), then its separate fields."""
    names = {}
    for name, src, col, _, dt in column_fields(spec):
        names.setdefault(src, name if col == WHOLE else "F" if dt == types.float64 else "I")
    return [names[i] for i in range(len(names))]


@intrinsic
def make_table(typingctx, tag, sources):
    """``make_table("bodies", (F, I))``: the table value over its flat arrays, inside compiled code
    (the type a Python view over the same arrays has)."""
    if not isinstance(tag, types.StringLiteral) or not isinstance(sources, types.BaseTuple):
        return None
    typ = TableType(tag.literal_value, column_fields(SPECS[tag.literal_value]), tuple(sources.types))

    def codegen(context, builder, sig, args):
        st = cgutils.create_struct_proxy(typ)(context, builder)
        for i in range(len(typ.sources)):
            setattr(st, f"s{i}", builder.extract_value(args[1], i))
        return impl_ret_borrowed(context, builder, typ, st._getvalue())

    return typ(tag, sources), codegen
