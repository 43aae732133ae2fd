#!/usr/bin/python3
"""StentGraftPlannerLib.CliRun: the CLI looked up at run time, started without display update,
and a run in flight followed and abandoned, with fakes standing for Slicer's objects."""
import os
import sys
import types
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from StentGraftPlannerLib import CliRun  # noqa: E402


class FakeCliNode:
    """The methods of vtkMRMLCommandLineModuleNode that CliRun calls, with a record of them."""

    def __init__(self, busy=True):
        self.busy = busy
        self.observers = {}
        self.nextTag = 1
        self.cancelled = 0

    def AddObserver(self, event, callback):
        tag, self.nextTag = self.nextTag, self.nextTag + 1
        self.observers[tag] = (event, callback)
        return tag

    def RemoveObserver(self, tag):
        del self.observers[tag]  # a KeyError: a tag removed twice or never added

    def IsBusy(self):
        return self.busy

    def Cancel(self):
        self.cancelled += 1


class FakeCli:
    """slicer.cli: records each run's arguments."""

    def __init__(self):
        self.calls = []

    def run(self, *args, **kwargs):
        self.calls.append((args, kwargs))
        return FakeCliNode()


CLI_MODULE = object()


class CliModuleTest(unittest.TestCase):
    def test_LoadedCli_IsFound(self):
        modules = types.SimpleNamespace(stentgraftsimulation=CLI_MODULE)
        self.assertIs(CliRun.cliModule(modules), CLI_MODULE)

    def test_MissingCli_IsARuntimeErrorThatSaysWhatToDo(self):
        # Issue 14 item 2: Slicer under --disable-cli-modules, or an incomplete install.
        with self.assertRaises(RuntimeError) as raised:
            CliRun.cliModule(types.SimpleNamespace(segmentations=object()))
        message = str(raised.exception)
        self.assertIn("StentGraftSimulation", message)
        self.assertIn("--disable-cli-modules", message)
        self.assertIn("reinstall", message)

    def test_MissingCli_StartsNothing(self):
        cli = FakeCli()
        with self.assertRaises(RuntimeError):
            CliRun.startCli(cli, types.SimpleNamespace(), {}, waitForCompletion=False)
        self.assertEqual(cli.calls, [])


class StartCliTest(unittest.TestCase):
    def test_RunsWithoutDisplayUpdate(self):
        # Issue 14 item 3: a display update puts the lumen label map on every slice view.
        for wait in (False, True):
            cli, parameters = FakeCli(), {"seed": "node"}
            CliRun.startCli(cli, types.SimpleNamespace(stentgraftsimulation=CLI_MODULE), parameters, wait)
            (args, kwargs), = cli.calls
            self.assertEqual(args, (CLI_MODULE, None, parameters))
            self.assertEqual(kwargs, {"wait_for_completion": wait, "update_display": False})


class PlanningRunTest(unittest.TestCase):
    def run_(self, busy=True):
        node = FakeCliNode(busy)
        run = CliRun.PlanningRun(node, "/tmp/report.json", "parameter node")
        run.observe(("ModifiedEvent", "StatusModifiedEvent"), lambda caller, event: None)
        return node, run

    def test_Steps_ProgressWhileBusy_ThenFinishOnce(self):
        node, run = self.run_()
        self.assertEqual(run.step(), CliRun.PROGRESS)
        node.busy = False
        self.assertEqual([run.step(), run.step()], [CliRun.FINISH, None])  # the two events of one end

    def test_SceneClose_CancelsTheBusyCliAndRemovesItsObservers(self):
        # Issue 14 item 4: a run left going reads its outputs into the closed scene's nodes.
        node, run = self.run_()
        self.assertEqual(len(node.observers), 2)
        run.abandon()
        self.assertEqual(node.cancelled, 1)
        self.assertEqual(node.observers, {})
        self.assertEqual(run.observers, [])
        self.assertIsNone(run.step())  # a later event, or a finish already scheduled, does nothing
        node.busy = False
        self.assertIsNone(run.step())

    def test_AbandonAfterTheEnd_CancelsNothing(self):
        node, run = self.run_(busy=False)
        self.assertEqual(run.step(), CliRun.FINISH)
        run.abandon()
        self.assertEqual(node.cancelled, 0)
        self.assertEqual(node.observers, {})
        run.removeObservers()  # again: nothing left to remove, no error


class OutcomeTest(unittest.TestCase):
    """Issue 33 item 7: a cancel is not a failure, and the progress line names the CLI's stage."""

    def test_Statuses_GiveTheirOutcome(self):
        # vtkMRMLCommandLineModuleNode: Cancelled 0x08, Completed 0x20, CompletedWithErrors 0x60.
        self.assertEqual(CliRun.runOutcome(0x08), CliRun.CANCELLED)
        self.assertEqual(CliRun.runOutcome(0x20), CliRun.COMPLETED)
        self.assertEqual(CliRun.runOutcome(0x60), CliRun.FAILED)
        self.assertEqual(CliRun.runOutcome(0x00), CliRun.FAILED)  # Idle: never ran

    def test_Cancel_IsReportedAsACancelWithoutAnErrorDialog(self):
        status, dialog = CliRun.finishedMessage(CliRun.CANCELLED)
        self.assertIn("cancelled", status)
        self.assertNotIn("failed", status)
        self.assertIsNone(dialog)

    def test_Failure_ShowsTheErrorText(self):
        status, dialog = CliRun.finishedMessage(CliRun.FAILED, "ERROR: seed 5000 outside the image")
        self.assertEqual(status, "The planning run failed.")
        self.assertIn("ERROR: seed 5000 outside the image", dialog)
        self.assertEqual(CliRun.finishedMessage(CliRun.COMPLETED), ("Done.", None))

    def test_StageMessage_IsReadFromTheModuleDescriptionText(self):
        # SEM's ModuleDescription operator<< ends with its ModuleProcessInformation; Slicer copies the
        # CLI's <filter-comment> (here with the quotes and spaces SlicerProgress writes) into it.
        text = ("Category: Vascular\nTitle: Stent Graft Simulation\n  Description: ProgressMessage in a text\n"
                "ProcessInformation: \n  Abort: 0\n  Progress: 0.42\n  Stage Progress: 0\n"
                '  ProgressMessage:  "Segmenting the lumen" \n  ElapsedTime: 3.5\n')
        self.assertEqual(CliRun.stageMessage(text), "Segmenting the lumen")
        self.assertEqual(CliRun.progressText(42.4, CliRun.stageMessage(text)), "Segmenting the lumen... (42 %)")

    def test_BeforeTheFirstStage_TheLineSaysTheRunIsStarting(self):
        text = "ProcessInformation: \n  Abort: 0\n  Progress: 0\n  ProgressMessage: \n  ElapsedTime: 0\n"
        self.assertEqual(CliRun.stageMessage(text), "")
        self.assertEqual(CliRun.progressText(0, CliRun.stageMessage(text)), "Starting the planning run... (0 %)")
        self.assertNotIn("Running", CliRun.progressText(0, ""))


if __name__ == "__main__":
    unittest.main()
