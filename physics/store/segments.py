"""A record of arrays of different lengths as compiled code sees it: two buffers and a directory.

numba passes a namedtuple of k arrays to a function as k array structs, 7k machine words copied
at every call (docs/flat-step.md); the global joint system's 19 arrays made every call of the
joint passes cost some 130 words before any work.  A ``SegmentsType`` value holds only two
1-D buffers: every integer field lies in ``I``, every float field in ``F``, one after another,
and ``I`` begins with a directory of (start, rows) per field.  ``R.x`` builds the field's view
where it is read: two loads from the directory and the indexing.  A field may be 2-D with a
fixed width (rows of ``width`` items).  The kernels' source does not change.

The Python side is a ``Segments`` class per record (``segments_class``): its fields are numpy
views of the same buffers, so Python code reads and writes the same memory.  Built on numba's
documented extension API (a type, its data model, attribute typing and lowering, typeof, unbox),
as store/table_type.py is.
"""
from __future__ import annotations

import numpy as np
from numba import typeof, types
from numba.core import cgutils
from numba.core.imputils import impl_ret_borrowed
from numba.core.typing.templates import AttributeTemplate
from numba.extending import infer_getattr, lower_getattr_generic, register_model, typeof_impl, unbox
from numba.np.arrayobj import make_array, populate_array

from .table_type import SourcesModel, SourcesType
from .table_view import unbox_sources

INT, FLOAT = 0, 1  # the buffers: a field's ``src``


class SegmentsType(SourcesType):
    """``fields``: per field (name, src, directory index, width or 0 for 1-D, dtype); ``sources``:
    the numba types of ``I`` and ``F``."""

    def __init__(self, tag: str, fields: tuple, sources: tuple):
        super().__init__(tag, fields, sources, "Segments")

    def field_type(self, name: str):
        _, _, _, width, dt = self.by_name[name]
        return types.Array(dt, 1 if width == 0 else 2, "C")


register_model(SegmentsType)(SourcesModel)  # the value is the two buffers, as a table's is its sources
unbox(SegmentsType)(unbox_sources)


@infer_getattr
class _SegmentsAttributes(AttributeTemplate):
    key = SegmentsType

    def generic_resolve(self, typ, attr):
        if attr in typ.by_name:
            return typ.field_type(attr)


@lower_getattr_generic(SegmentsType)
def _field(context, builder, typ, value, attr):
    """The field's view: its start and rows read from the directory at the head of ``I``."""
    _, src, k, width, dt = typ.by_name[attr]
    st = cgutils.create_struct_proxy(typ)(context, builder, value=value)
    head = make_array(typ.sources[INT])(context, builder, value=st.s0)
    intp = lambda v: context.get_constant(types.intp, v)
    start = builder.load(cgutils.gep(builder, head.data, intp(2 * k)))
    rows = builder.load(cgutils.gep(builder, head.data, intp(2 * k + 1)))
    base = make_array(typ.sources[src])(context, builder, value=getattr(st, f"s{src}"))
    item = intp(context.get_abi_sizeof(context.get_data_type(dt)))
    data = cgutils.gep(builder, base.data, start)
    resty = typ.field_type(attr)
    if width == 0:
        shape, strides = [rows], [item]
    else:
        shape, strides = [rows, intp(width)], [builder.mul(item, intp(width)), item]
    out = make_array(resty)(context, builder)
    populate_array(out, data=data, shape=shape, strides=strides, itemsize=item, meminfo=base.meminfo)
    return impl_ret_borrowed(context, builder, resty, out._getvalue())


class Segments:
    """A record's fields (``_fields``) as numpy views of ``_sources`` = (I, F); subclasses are made
    by ``segments_class`` and built with each field's row count: ``System(a=3, b=10)``, zeroed."""

    __slots__ = ("_numba_type", "_sources")
    _fields: tuple = ()
    _spec: dict = {}
    _tag = ""

    def __init__(self, **rows):
        if set(rows) != set(self._fields):
            raise TypeError(f"{type(self).__name__} takes the row counts of {', '.join(self._fields)}")
        counts = {INT: 2 * len(self._fields), FLOAT: 0}  # the directory heads I
        place = {}
        for name in self._fields:
            src, width = self._spec[name]
            n = int(rows[name])
            place[name] = (src, counts[src], n, width)
            counts[src] += n * max(width, 1)
        I = np.zeros(counts[INT], np.int64)
        F = np.zeros(counts[FLOAT], np.float64)
        bufs = (I, F)
        for k, name in enumerate(self._fields):
            src, start, n, width = place[name]
            I[2 * k], I[2 * k + 1] = start, n
            a = bufs[src][start:start + n * max(width, 1)]
            object.__setattr__(self, name, a if width == 0 else a.reshape(n, width))
        self._sources = bufs
        layout = tuple((name, self._spec[name][0], k, self._spec[name][1],
                        types.int64 if self._spec[name][0] == INT else types.float64)
                       for k, name in enumerate(self._fields))
        self._numba_type = SegmentsType(self._tag, layout, (typeof(I), typeof(F)))

    def rows(self) -> dict:
        """Each field's row count (what a copy of this record is built with)."""
        return {name: len(getattr(self, name)) for name in self._fields}

    def __repr__(self):
        return f"{type(self).__name__}({', '.join(self._fields)})"


def segments_class(name: str, spec: dict, tag: str) -> type:
    """The Segments subclass of a record: ``spec`` maps each field to (INT or FLOAT, width)."""
    return type(name, (Segments,), {"__slots__": tuple(spec), "_fields": tuple(spec), "_spec": dict(spec),
                                    "_tag": tag})


@typeof_impl.register(Segments)
def _typeof_segments(val, c):
    return val._numba_type
