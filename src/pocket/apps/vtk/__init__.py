"""VTK output for ParaView: a solved state or a load path as files of its profile, surface and indenter.

``files`` (the meshes of a state, their field data, and the files and series written), ``resampling``
(the profiles of a series on one set of Lagrangian radii), ``revolve`` (a meridian revolved into a
surface) and ``indentermesh`` (the indenter's lower surface).
"""
