"""The Python side of a store table: its fields as attributes, its arrays as one compact value.

``view_class("Bodies", BODY_FIELDS)`` makes the class whose instances store/table.py hands out
as ``table.view``: ``view.x`` is the column array, as the namedtuple it replaces gave, so Python
code reads and writes the store's memory.  Passed to a compiled function, an instance is typed
as a ``TableType`` (store/table_type.py) and unboxes only its sources: the ``Columns`` arrays
``F``, ``I`` and the separate fields, found from the columns themselves when they are one
layout, else each field as an array of its own.
"""
from __future__ import annotations

import numpy as np
from numba import typeof
from numba.core import cgutils
from numba.extending import NativeValue, box, typeof_impl, unbox

from .table_type import SPECS, WHOLE, TableType, column_fields


class TableView:
    """A table's fields (``_fields`` in declaration order) as attributes, and ``_sources``, the
    arrays compiled code receives; subclasses are made by ``view_class``."""

    __slots__ = ("_numba_type", "_sources")
    _fields: tuple = ()
    _tag = ""
    _layout: tuple = ()

    def __init__(self, *args, **fields):
        if args:
            fields.update(zip(self._fields, args))
        missing = [f for f in self._fields if f not in fields]
        if missing or len(fields) != len(self._fields):
            raise TypeError(f"{type(self).__name__} takes the fields {', '.join(self._fields)}")
        for k in self._fields:
            object.__setattr__(self, k, fields[k])
        sources, layout = _sources(self._layout, fields)
        self._sources = sources
        self._numba_type = TableType(self._tag, layout, tuple(typeof(a) for a in sources))

    def _replace(self, **fields):
        """A view with some fields replaced (as a namedtuple's ``_replace``)."""
        return type(self)(**{k: fields.get(k, getattr(self, k)) for k in self._fields})

    def __iter__(self):
        return (getattr(self, k) for k in self._fields)

    def __len__(self):
        return len(self._fields)

    def __repr__(self):
        return f"{type(self).__name__}({', '.join(self._fields)})"


def _base(a: np.ndarray):
    b = a.base
    return b if isinstance(b, np.ndarray) and b.base is None else None


def _sources(layout: tuple, fields: dict):
    """(the source arrays, the layout) of ``fields``: the Columns layout when every column is
    where it says over two shared C-ordered 2-D arrays, else one source per field."""
    srcs: dict[int, np.ndarray] = {}
    ok = True
    for name, src, col, width, _ in layout:
        a = fields[name]
        if col == WHOLE:
            srcs[src] = a
            continue
        b = _base(a)
        if b is None or b.ndim != 2 or not b.flags.c_contiguous or srcs.setdefault(src, b) is not b:
            ok = False
            break
        off = a.__array_interface__["data"][0] - b.__array_interface__["data"][0]
        if off != col * b.itemsize or a.strides[0] != b.strides[0] or a.shape[0] != b.shape[0]:
            ok = False
            break
    if ok and len(srcs) == 1 + max(f[1] for f in layout):
        return tuple(srcs[i] for i in range(len(srcs))), layout
    each = tuple((name, i, WHOLE, 0, dt) for i, (name, _, _, _, dt) in enumerate(layout))
    return tuple(fields[f[0]] for f in layout), each


#: tag -> the table's view class
CLASSES: dict[str, type] = {}


def view_class(name: str, spec: dict, tag: str) -> type:
    """The TableView subclass of a table (fields and their dtypes from ``spec``)."""
    SPECS[tag] = spec
    CLASSES[tag] = type(name, (TableView,), {"__slots__": tuple(spec), "_fields": tuple(spec), "_tag": tag,
                                             "_layout": column_fields(spec)})
    return CLASSES[tag]


def rebuilt(tag: str, layout: tuple, sources: tuple) -> TableView:
    """The Python view of a table value compiled code returned (its sources and their layout)."""
    fields = {}
    for name, src, col, width in layout:
        a = sources[src]
        fields[name] = a if col == WHOLE else a[:, col] if width == 0 else a[:, col:col + width]
    return CLASSES[tag](**fields)


@typeof_impl.register(TableView)
def _typeof_view(val, c):
    return val._numba_type


@unbox(TableType)
def unbox_sources(typ, obj, c):
    """Each source array unboxed from the object's ``_sources`` into the value's ``s0``, ``s1``, ...
    (a table view's; store/segments.py's records unbox the same way)."""
    st = cgutils.create_struct_proxy(typ)(c.context, c.builder)
    srcs = c.pyapi.object_getattr_string(obj, "_sources")
    err = cgutils.alloca_once_value(c.builder, cgutils.false_bit)
    for i, sty in enumerate(typ.sources):
        item = c.pyapi.tuple_getitem(srcs, i)   # borrowed
        nv = c.unbox(sty, item)
        setattr(st, f"s{i}", nv.value)
        with c.builder.if_then(nv.is_error):
            c.builder.store(cgutils.true_bit, err)
    c.pyapi.decref(srcs)
    return NativeValue(st._getvalue(), is_error=c.builder.load(err))


@box(TableType)
def _box_view(typ, val, c):
    """A table value returned to Python: its sources boxed, the view rebuilt over them."""
    st = cgutils.create_struct_proxy(typ)(c.context, c.builder, value=val)
    items = [c.box(t, getattr(st, f"s{i}")) for i, t in enumerate(typ.sources)]
    srcs = c.pyapi.tuple_pack(items)
    for it in items:
        c.pyapi.decref(it)
    layout = tuple((n, s, col, w) for n, s, col, w, _ in typ.fields)
    fn = c.pyapi.unserialize(c.pyapi.serialize_object(rebuilt))
    args = [c.pyapi.unserialize(c.pyapi.serialize_object(x)) for x in (typ.tag, layout)]
    out = c.pyapi.call_function_objargs(fn, args + [srcs])
    c.pyapi.decref(srcs)
    return out
