"""Fitting a rubber law to a user's tests of the clamped sheet (``pocket fit``).

``case`` (what a user asks a fit: flags or a case file's ``[fit]`` table), ``data`` (the tests' CSV files
read into SI arrays), ``checks`` (a unit gone wrong, found before any solve), ``keys`` (the parameters a fit
can vary), ``model`` (the model's values at the data and the residuals), ``start`` (where a fit starts),
``leastsquares`` (the fit itself, and its result), ``stats`` (standard errors, correlations, linearised
intervals), ``intervals`` (the profile-likelihood intervals) and ``report`` (the summary, the fitted
sheet's case file and the figure). A closed capsule's test between two plates has its own ``capsuledata`` (the
force-gap CSV), ``capsulemodel`` (its gaps at the forces, its residuals and keys, P_I among them) and
``capsuletest`` (its fit, on the same search and statistics).
"""
