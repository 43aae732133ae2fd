"""The parts of the StentGraftPlanner scripted module that do not need Slicer.

Slicer's module scanner loads every ``*.py`` file next to ``StentGraftPlanner.py`` as a module
candidate, so these helpers live in a package one folder down (the SlicerHeart pattern, STYLE.md
B7). Everything here runs under a plain Python 3 with the standard library only, and is tested
that way in CTest (``Testing/Python``).

- ``Settings``: the panel's settings, their defaults (equal to the CLI XML's), their storage as
  parameter-node strings, and the parameter dictionary handed to ``slicer.cli.run``.
- ``CliRun``: the CLI looked up when a run starts, started without display update, and a run in
  flight followed and, when the scene closes, cancelled.
- ``Results``: reading what the CLI returns (return parameters, the diameter-profile table, the JSON
  report) and formatting, at clinical precision and in words, the order list beside the anatomy,
  the device recommendation and the fit check.
- ``Outcome``: what a completed run returned, as the panel's values, table rows and text (a run
  whose device selection found nothing among them: a result, not a failure).
- ``Replan``: the panel's Re-plan: the landmarks of a run read back and compared with their dragged
  positions, the re-plan's CLI parameters (moved and given landmarks in RAS, the last run's or the
  edited lumen), and what changed between two runs, in words at clinical precision.
- ``EditConfiguration``: the editable order list: the configuration a run simulated as rows, the
  catalogue's entries for each, the edited file and the run that simulates it (issue 47).
- ``Appearance``: colours and opacities of the outputs and of the plot series, and the colours of
  the simulated graft's components.
"""
