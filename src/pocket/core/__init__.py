"""The vocabulary every layer of pocket shares: states, errors, input checks, units, rubbers, fluids,
indenters, the membrane's reference surfaces (``geometries``), solver records, the reported keys with their
units and meanings (``reported``), and the compiled-code cache both solvers use (``compiled``).

Nothing here imports a solver or an application; the solvers (``pocket.shooting``,
``pocket.fem``, ``pocket.analytical``) build on it, the applications
(``pocket.apps``) on them, and the command line (``pocket.cli``) and the
validation suite (``pocket.validation``) on top.
"""
