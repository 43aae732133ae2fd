"""Starting the StentGraftSimulation CLI and following one run of it, without Slicer.

StentGraftPlanner.py hands in Slicer's objects (``slicer.modules``, ``slicer.cli``, the CLI
node); everything here only calls the few methods named below, so a fake object tests it.

- ``cliModule``: the CLI module looked up when a run starts. The scripted module does not declare
  the CLI in its ``dependencies``: Slicer started with ``--disable-cli-modules`` (its generic
  module tests) would then refuse to load the whole panel. A missing CLI is an error of the run.
- ``startCli``: ``slicer.cli.run`` with ``update_display=False``. With a display update Slicer
  makes the lumen label map the active label volume and puts it on every slice view's label
  layer, where hiding the node does not remove it; the panel shows the segmentation instead.
- ``PlanningRun``: one run in flight. Its CLI node's events say what to do next (``step``), and
  ``abandon`` stops it when the scene closes: observers removed first (nothing reaches a closed
  panel), then the CLI node cancelled, so that Slicer's CLI logic does not read the outputs into
  nodes the closed scene has removed.
"""

#: The CLI's module name (its XML file and executable), for messages.
CLI_MODULE_NAME = "StentGraftSimulation"

#: Its attribute in ``slicer.modules`` (Slicer lower-cases module names there).
CLI_MODULE_ATTRIBUTE = CLI_MODULE_NAME.lower()


def cliModule(modules):
    """The StentGraftSimulation module of ``modules`` (``slicer.modules``), or RuntimeError."""
    module = getattr(modules, CLI_MODULE_ATTRIBUTE, None)
    if module is None:
        raise RuntimeError(
            "The %s CLI module is not loaded, so the planning run cannot start. It is part of the "
            "StentGraftPlanner extension: check that the extension is installed completely (reinstall "
            "it from the Extensions Manager) and that Slicer was not started with --disable-cli-modules, "
            "then restart Slicer." % CLI_MODULE_NAME
        )
    return module


def startCli(cli, modules, parameters, waitForCompletion):
    """Run StentGraftSimulation with ``parameters``: ``cli`` is ``slicer.cli``; returns its CLI node.

    Raises RuntimeError (``cliModule``) before anything runs when the CLI is not loaded.
    """
    return cli.run(cliModule(modules), None, parameters, wait_for_completion=waitForCompletion,
                   update_display=False)


#: What a CLI node event calls for (``PlanningRun.step``).
PROGRESS, FINISH = "progress", "finish"


class PlanningRun:
    """One CLI run in flight: its CLI node, the temporary report path, the visual report's path (None:
    not asked for) and the parameter node.

    cliNode needs AddObserver(event, callback) -> tag, RemoveObserver(tag), IsBusy() and Cancel().
    """

    def __init__(self, cliNode, reportPath, parameterNode, reportHtmlPath=None):
        self.cliNode = cliNode
        self.reportPath = reportPath
        self.reportHtmlPath = reportHtmlPath  # the visual report: kept after the run (the user opens it)
        self.parameterNode = parameterNode
        self.replan = None  # a re-plan's Replan.ReplanInputs (what it started from), None for a plan
        self.observers = []
        self.finishing = False
        self.abandoned = False

    def observe(self, events, callback):
        """Call ``callback(caller, event)`` on each of the CLI node's ``events``."""
        for event in events:
            self.observers.append(self.cliNode.AddObserver(event, callback))

    def removeObservers(self):
        for tag in self.observers:
            self.cliNode.RemoveObserver(tag)
        self.observers = []

    def step(self):
        """What an event of the CLI node calls for: PROGRESS while it is busy, FINISH once when it
        has ended, then None; None at all times once the run is abandoned."""
        if self.abandoned:
            return None
        if self.cliNode.IsBusy():
            return PROGRESS
        if self.finishing:
            return None
        self.finishing = True
        return FINISH

    def abandon(self):
        """Stop following the run and cancel the CLI if it is still busy (the scene is closing).

        A finish already scheduled sees ``abandoned`` and does nothing (``step`` returns None).
        """
        self.abandoned = True
        self.removeObservers()
        if self.cliNode.IsBusy():
            self.cliNode.Cancel()


#: How a run ended (``runOutcome``).
COMPLETED, CANCELLED, FAILED = "completed", "cancelled", "failed"

#: vtkMRMLCommandLineModuleNode's status bits (Libs/MRML/CLI/vtkMRMLCommandLineModuleNode.h), for
#: fakes and for a node whose class attributes are not at hand.
STATUS_CANCELLED, STATUS_COMPLETED, STATUS_ERRORS_MASK = 0x08, 0x20, 0x40


def runOutcome(status):
    """How a CLI node that is no longer busy ended, from its ``GetStatus()``: CANCELLED (the user's
    Cancel, or a closing scene), FAILED (Completed with the errors bit: a non-zero exit, an output
    Slicer could not load, or a status that is not Completed) or COMPLETED."""
    if status & STATUS_CANCELLED:
        return CANCELLED
    if status & STATUS_ERRORS_MASK or not status & STATUS_COMPLETED:
        return FAILED
    return COMPLETED


def finishedMessage(outcome, errorText=""):
    """The panel's status line and, for a failure only, the text of the error dialog (else None)."""
    if outcome == CANCELLED:
        return "The planning run was cancelled; nothing was loaded.", None
    if outcome == FAILED:
        return "The planning run failed.", "The planning run failed.\n\n" + (errorText or "(no error text)")
    return "Done.", None


#: The line of ``GetModuleDescriptionAsString()`` that holds the CLI's latest stage comment (SEM's
#: ModuleProcessInformation printed: "  ProgressMessage: <text>"; Slicer copies the last
#: <filter-comment> there, or the last <filter-name> when a stage has no comment).
_PROGRESS_MESSAGE = "ProgressMessage:"


def stageMessage(moduleDescriptionText):
    """The stage the CLI last reported (its <filter-comment>, e.g. "Segmenting the lumen"), read from
    a CLI node's ``GetModuleDescriptionAsString()``; "" before the first stage. (The message itself is
    in SEM's ModuleProcessInformation, which Slicer's Python does not wrap.)"""
    for line in (moduleDescriptionText or "").splitlines():
        stripped = line.strip()
        if stripped.startswith(_PROGRESS_MESSAGE):
            return stripped[len(_PROGRESS_MESSAGE):].strip().strip('"').strip()
    return ""


def progressText(percent, stage):
    """The panel's line while the CLI runs: the stage it reports and the overall percentage."""
    return "%s... (%d %%)" % (stage or "Starting the planning run", int(round(percent)))
