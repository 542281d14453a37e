"""Applications on top of the solvers, in physical units and for users' tasks.

``cases`` (case files, read by ``tomlfiles``), ``rubbers`` (the rubber law and the fluid as case files
and command lines give them, checked), ``physical`` (a case resolved to the dimensionless
model and back to SI), ``inverse`` (the load that gives a target value),
``casefile`` (``pocket run``), ``design`` (soft buttons), ``sense`` (force from
pressure), ``sweep`` (parameter grids on any executor) with ``sweepfile`` (its
CSV journal), ``workers`` (local processes that die with their parent) and ``cluster`` (a dask
cluster that says when it cannot run the sweep),
``slopes``, ``vtkfiles`` (ParaView output), ``folders`` (outputs checked first,
written whole or not at all) with ``ledger`` (the checksums of what pocket wrote), ``provenance``
and ``solvers`` (the solvers by name).
"""
