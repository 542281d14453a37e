"""Applications on top of the solvers, in physical units and for users' tasks.

``cases`` (case files, read by ``tomlfiles``), ``rubbers`` (the rubber law and the fluid as case files
and command lines give them, checked), ``physical`` (a case resolved to the dimensionless
model and back to SI), ``inverse`` (the load that gives a target value),
``casefile`` (``pocket run``), ``design`` (soft buttons), ``sense`` (force from
pressure), ``forcerange`` (a force past the end of the range, refused in the user's unit),
``contactpatch`` (the contact patch a state reports), ``slopes``, ``folders`` (outputs checked first,
written whole or not at all) with ``ledger`` (the checksums of what pocket wrote), ``provenance``
and ``solvers`` (the solvers by name).

Three subpackages, independent of each other: ``fit`` (a rubber law fitted to a user's tests),
``sweep`` (parameter grids on any executor, their CSV journal, local workers and dask clusters) and
``vtk`` (ParaView output).
"""
