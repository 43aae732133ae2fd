#!/usr/bin/python3
"""StentGraftPlannerLib.Settings: defaults, parameter-node strings, validation and the CLI dictionary.

Run: /usr/bin/python3 -m unittest discover -s StentGraftPlanner/Testing/Python (stdlib only).
"""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from StentGraftPlannerLib import Settings  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "Data")


class Node:
    """Stands for an MRML node: the CLI dictionary must pass nodes through untouched."""

    def __init__(self, name):
        self.name = name


def allNodes():
    return {role.name: Node(role.name) for role in Settings.NODE_ROLES}


#: One selected point in every point list (the seed and the landmarks).
ONE_POINT = {name: 1 for name in Settings.POINT_ROLES}


class SettingsStringsTest(unittest.TestCase):
    def test_RoundTrip_GivesBackEveryValueExactly(self):
        settings = Settings.defaultSettings()
        settings.update(lowerHu=123.25, acmToleranceMm=1e-7, verticesPerRing=32, thresholdMode="manual",
                        deviceFamily="Zenith Flex", deviceCatalogPath="/tmp/my devices.json")
        back, problems = Settings.settingsFromStrings(Settings.settingsToStrings(settings))
        self.assertEqual(back, settings)
        self.assertEqual(problems, [])

    def test_MissingOrEmptyStrings_FallBackToDefaultsSilently(self):
        back, problems = Settings.settingsFromStrings({"lowerHu": "", "upperHu": None})
        self.assertEqual(back, Settings.defaultSettings())
        self.assertEqual(problems, [])

    def test_UnreadableValues_FallBackAndNameTheValue(self):
        back, problems = Settings.settingsFromStrings(
            {"lowerHu": "abc", "verticesPerRing": "16.5", "thresholdMode": "magic", "acmTau": "nan"})
        self.assertEqual(back, Settings.defaultSettings())
        self.assertEqual(len(problems), 4)
        self.assertTrue(any("'abc'" in p and "lowerHu" in p for p in problems), problems)

    def test_UnknownSettingName_IsRejected(self):
        with self.assertRaises(KeyError):
            Settings.settingsToStrings({"noSuchSetting": 1})

    def test_FormatNumber_IsShortAndExact(self):
        self.assertEqual(Settings.formatNumber(20.0), "20")
        self.assertEqual(Settings.formatNumber(0.1), "0.1")
        self.assertEqual(float(Settings.formatNumber(1 / 3)), 1 / 3)


class SchemaTest(unittest.TestCase):
    def test_NamesAndWidgets_AreUnique(self):
        names = [s.name for s in Settings.SETTINGS] + [r.name for r in Settings.NODE_ROLES]
        self.assertEqual(len(names), len(set(names)))
        widgets = [s.widget for s in Settings.SETTINGS]
        self.assertEqual(len(widgets), len(set(widgets)))

    def test_Defaults_HaveTheirKindsType(self):
        for s in Settings.SETTINGS:
            expected = {"float": float, "int": int, "enum": str, "str": str}[s.kind]
            self.assertIsInstance(s.default, expected, s.name)
            if s.kind == "enum":
                self.assertIn(s.default, s.choices, s.name)


class DeploymentSettingsTest(unittest.TestCase):
    """Issue 29: the main body's side and the deployment offset, with the CLI's defaults (the XML's
    ipsilateralSide and deploymentOffsetMm; check_cli_contract.py compares them and the widget's range
    with the XML itself)."""

    def test_Defaults_AreTheClis(self):
        side, offset = Settings.SETTINGS_BY_NAME["ipsilateralSide"], Settings.SETTINGS_BY_NAME["deploymentOffsetMm"]
        self.assertEqual((side.kind, side.default, side.choices, side.cli),
                         ("enum", "auto", ("auto", "right", "left"), True))
        self.assertEqual((offset.kind, offset.default, offset.cli), ("float", 0.0, True))
        self.assertEqual((side.widget, offset.widget), ("ipsilateralSideComboBox", "deploymentOffsetMmSpinBox"))

    def test_Values_AreSentToTheCliAndSurviveTheParameterNode(self):
        settings = dict(Settings.defaultSettings(), ipsilateralSide="left", deploymentOffsetMm=-12.5)
        parameters = Settings.buildCliParameters(settings, allNodes(), ONE_POINT, "/tmp/report.json")
        self.assertEqual((parameters["ipsilateralSide"], parameters["deploymentOffsetMm"]), ("left", "-12.5"))
        back, problems = Settings.settingsFromStrings(Settings.settingsToStrings(settings))
        self.assertEqual((back["ipsilateralSide"], back["deploymentOffsetMm"]), ("left", -12.5))
        self.assertEqual(problems, [])

    def test_UnknownSide_FallsBackToAuto(self):
        back, problems = Settings.settingsFromStrings({"ipsilateralSide": "both", "deploymentOffsetMm": "x"})
        self.assertEqual((back["ipsilateralSide"], back["deploymentOffsetMm"]), ("auto", 0.0))
        self.assertEqual(len(problems), 2)
        self.assertTrue(any("'both'" in p and "ipsilateralSide" in p for p in problems), problems)

class DeviceArgumentTest(unittest.TestCase):
    def test_Forms(self):
        self.assertEqual(Settings.deviceArgument("auto", 0), "auto")
        self.assertEqual(Settings.deviceArgument("", 26), "auto")
        self.assertEqual(Settings.deviceArgument("  Excluder ", 0), "Excluder")
        self.assertEqual(Settings.deviceArgument("Excluder", 28.5), "Excluder:28.5")
        self.assertEqual(Settings.deviceArgument("Endurant II", 25.0), "Endurant II:25")

    def test_ColonInFamily_IsRejected(self):
        with self.assertRaisesRegex(ValueError, "'Bad:Name'"):
            Settings.deviceArgument("Bad:Name", 0)


class CatalogFamiliesTest(unittest.TestCase):
    def test_SampleCatalog_GivesUniqueNamesInFileOrder(self):
        with open(os.path.join(DATA, "devices-sample.json")) as f:
            self.assertEqual(Settings.catalogFamilies(f.read()), ["Endurant II", "Excluder", "Zenith Flex"])

    def test_TopLevelListAndDevicesKey_AreRead(self):
        self.assertEqual(Settings.catalogFamilies('[{"family": "A"}]'), ["A"])
        self.assertEqual(Settings.catalogFamilies('{"devices": [{"name": "B"}]}'), ["B"])

    def test_NoFamily_RaisesValueError(self):
        for text in ("{}", "[]", '{"families": [1, {"size": 3}]}', "not json"):
            with self.assertRaises(ValueError, msg=text):
                Settings.catalogFamilies(text)


class ValidateTest(unittest.TestCase):
    def test_Defaults_AreValid(self):
        Settings.validateSettings(Settings.defaultSettings())

    def test_ManualWindowUpsideDown_NamesBothValues(self):
        settings = dict(Settings.defaultSettings(), thresholdMode="manual", lowerHu=700.0, upperHu=600.0)
        with self.assertRaisesRegex(ValueError, "700 HU.*600 HU"):
            Settings.validateSettings(settings)

    def test_UpsideDownWindowInAutoMode_IsIgnored(self):
        Settings.validateSettings(dict(Settings.defaultSettings(), lowerHu=700.0, upperHu=600.0))

    def test_OversizingRange_MustBeOrderedAndBounded(self):
        for low, high in ((20.0, 10.0), (15.0, 15.0), (-5.0, 10.0), (10.0, 60.0)):
            settings = dict(Settings.defaultSettings(), oversizingMinPercent=low, oversizingMaxPercent=high)
            with self.assertRaisesRegex(ValueError, "oversizing range", msg=(low, high)):
                Settings.validateSettings(settings)

    def test_NegativeForcedDiameter_IsRejected(self):
        with self.assertRaisesRegex(ValueError, "-3 mm"):
            Settings.validateSettings(dict(Settings.defaultSettings(), deviceDiameterMm=-3.0))


class BuildCliParametersTest(unittest.TestCase):
    def build(self, settings=None, nodes=None, counts=ONE_POINT):
        return Settings.buildCliParameters(settings or Settings.defaultSettings(), nodes or allNodes(), counts,
                                           "/tmp/report.json")

    def test_Defaults_GiveEveryCliSettingWithItsType(self):
        parameters = self.build()
        for s in Settings.SETTINGS:
            if not s.cli:
                self.assertNotIn(s.name, parameters)
            elif s.kind == "float":  # as text: slicer.cli would format a float with six digits
                self.assertEqual(parameters[s.name], Settings.formatNumber(s.default), s.name)
                self.assertIs(type(parameters[s.name]), str, s.name)
            else:
                self.assertEqual(parameters[s.name], s.default, s.name)
                self.assertIs(type(parameters[s.name]), type(s.default), s.name)
        self.assertEqual(parameters["device"], "auto")
        self.assertEqual(parameters["proximalOversizingRange"], "10,20")  # pre-joined: no ", " from slicer.cli
        self.assertEqual(parameters["outputReport"], "/tmp/report.json")
        self.assertNotIn("deviceCatalog", parameters)  # the CLI's default: the bundled catalogue
        self.assertNotIn("neckRules", parameters)  # the CLI's default: the bundled hostile-neck rules

    def test_FloatSettings_KeepMoreThanSixSignificantDigits(self):
        # Issue 14 item 7: SetParameterAsDouble would send 0.00123457 and 1.23457e+06.
        settings = dict(Settings.defaultSettings(), acmToleranceMm=0.00123456789, maximumLumenVolumeMl=1234567.0,
                        lowerHu=-123.456789)
        parameters = self.build(settings)
        self.assertEqual(parameters["acmToleranceMm"], "0.00123456789")
        self.assertEqual(parameters["maximumLumenVolumeMl"], "1234567")
        self.assertEqual(parameters["lowerHu"], "-123.456789")
        for s in Settings.SETTINGS:
            if s.cli and s.kind == "float":
                self.assertEqual(float(parameters[s.name]), settings[s.name], s.name)  # exact round trip

    def test_Nodes_ArePassedThroughUnderTheirRoles(self):
        nodes = allNodes()
        parameters = self.build(nodes=nodes)
        for role in Settings.NODE_ROLES:
            self.assertIs(parameters[role.name], nodes[role.name])

    def test_DeviceChoices_AreCombined(self):
        settings = dict(Settings.defaultSettings(), deviceFamily="Excluder", deviceDiameterMm=28.5,
                        oversizingMinPercent=12.5, oversizingMaxPercent=25.0, deviceCatalogPath="/data/devices.json")
        parameters = self.build(settings)
        self.assertEqual(parameters["device"], "Excluder:28.5")
        self.assertEqual(parameters["proximalOversizingRange"], "12.5,25")
        self.assertEqual(parameters["deviceCatalog"], "/data/devices.json")

    def test_NeckRulesFile_IsSentOnlyWhenChosen(self):
        # Issue 12 item 4: the rule set is replaceable with --neckRules, like the device catalogue.
        settings = dict(Settings.defaultSettings(), neckRulesPath="/data/my rules.json")
        parameters = self.build(settings)
        self.assertEqual(parameters["neckRules"], "/data/my rules.json")  # unchanged: a path, spaces and all
        self.assertNotIn("deviceCatalog", parameters)
        self.assertEqual(Settings.SETTINGS_BY_NAME["neckRulesPath"].default, "")
        self.assertFalse(Settings.SETTINGS_BY_NAME["neckRulesPath"].cli)  # combined, not sent as itself
        self.assertNotIn("neckRulesPath", parameters)

    def test_VisualReport_IsSentOnlyWhenAPathIsGiven(self):
        # Issue 15 item 3: the panel asks for the HTML report and offers "Open report" after the run.
        self.assertNotIn("outputReportHtml", self.build())
        parameters = Settings.buildCliParameters(Settings.defaultSettings(), allNodes(), ONE_POINT, "/tmp/report.json",
                                                 "/cases/a b/StentGraftPlanner-CT-20261202-131500.html")
        self.assertEqual(parameters["outputReportHtml"], "/cases/a b/StentGraftPlanner-CT-20261202-131500.html")
        self.assertFalse(Settings.SETTINGS_BY_NAME["reportFolder"].cli)

    def test_ReportHtmlPath_InTheChosenFolderElseTheTemporaryOne_NamedSafely(self):
        self.assertEqual(Settings.reportHtmlPath("/cases", "/tmp/slicer", "CTA 1/2", "20261202-131500"),
                         "/cases/StentGraftPlanner-CTA_1_2-20261202-131500.html")
        self.assertEqual(Settings.reportHtmlPath("", "/tmp/slicer", "", "20261202-131500"),
                         "/tmp/slicer/StentGraftPlanner-volume-20261202-131500.html")

    def test_NeckRulesPath_SurvivesTheParameterNode(self):
        settings = dict(Settings.defaultSettings(), neckRulesPath="/tmp/rules.json")
        back, problems = Settings.settingsFromStrings(Settings.settingsToStrings(settings))
        self.assertEqual(back["neckRulesPath"], "/tmp/rules.json")
        self.assertEqual(problems, [])

    def test_WallOutputs_AreNewNodesPassedToTheCli(self):
        # Issue 12 item 6: the wall label map and the outer-wall surface, created like the other outputs.
        roles = Settings.NODE_ROLES_BY_NAME
        self.assertEqual((roles["outputWallLabelMap"].nodeClass, roles["outputWallLabelMap"].channel),
                         ("vtkMRMLLabelMapVolumeNode", "output"))
        self.assertEqual((roles["outputOuterWallModel"].nodeClass, roles["outputOuterWallModel"].channel),
                         ("vtkMRMLModelNode", "output"))
        for name in ("outputWallLabelMap", "outputOuterWallModel"):
            self.assertIn(roles[name], Settings.OUTPUT_ROLES)
            self.assertTrue(roles[name].defaultName, name)
        nodes = allNodes()
        parameters = self.build(nodes=nodes)
        self.assertIs(parameters["outputWallLabelMap"], nodes["outputWallLabelMap"])
        self.assertIs(parameters["outputOuterWallModel"], nodes["outputOuterWallModel"])
        for name in ("outputWallLabelMap", "outputOuterWallModel"):
            with self.assertRaisesRegex(ValueError, name):
                self.build(nodes=dict(allNodes(), **{name: None}))

    def test_RenalLandmarkWithoutPoints_IsLeftOut(self):
        for nodes, counts in ((allNodes(), {"seed": 1, "lowestRenalOstium": 0}),
                              (dict(allNodes(), lowestRenalOstium=None), {"seed": 1})):
            self.assertNotIn("lowestRenalOstium", self.build(nodes=nodes, counts=counts))

    def test_GivenLandmarksAndLumen_AreSentUnderTheClisNames(self):
        # Issue 45: the three landmarks beside the renal one, and a lumen segmentation with its labels.
        self.assertEqual(Settings.POINT_ROLES, ("seed", "lowestRenalOstium", "aorticBifurcation",
                                                "rightInternalIliacOrigin", "leftInternalIliacOrigin"))
        lumen = Settings.NODE_ROLES_BY_NAME["inputLumenSegmentation"]
        self.assertEqual((lumen.nodeClass, lumen.channel, lumen.required),
                         ("vtkMRMLLabelMapVolumeNode", "input", False))
        nodes = allNodes()
        settings = dict(Settings.defaultSettings(), lumenLabels="52,65,66")
        parameters = self.build(settings, nodes=nodes)
        for name in ("aorticBifurcation", "rightInternalIliacOrigin", "leftInternalIliacOrigin",
                     "inputLumenSegmentation"):
            self.assertIs(parameters[name], nodes[name], name)
        self.assertEqual(parameters["lumenLabels"], "52,65,66")
        self.assertEqual(self.build()["lumenLabels"], "")  # the CLI's default: every non-zero voxel

    def test_LandmarkWithoutPoints_IsLeftOutForTheCliToFind(self):
        for name in ("aorticBifurcation", "rightInternalIliacOrigin", "leftInternalIliacOrigin"):
            parameters = self.build(counts=dict(ONE_POINT, **{name: 0}))
            self.assertNotIn(name, parameters)
            self.assertIn("seed", parameters)
            self.assertNotIn(name, self.build(nodes=dict(allNodes(), **{name: None})))

    def test_NoLumenSegmentation_IsLeftOutForRegionGrowing(self):
        self.assertNotIn("inputLumenSegmentation", self.build(nodes=dict(allNodes(), inputLumenSegmentation=None)))

    def test_LumenLabels_SurviveTheParameterNode(self):
        settings = dict(Settings.defaultSettings(), lumenLabels="aorta, left common iliac")
        back, problems = Settings.settingsFromStrings(Settings.settingsToStrings(settings))
        self.assertEqual((back["lumenLabels"], problems), ("aorta, left common iliac", []))

    def test_MissingVolume_IsAValueError(self):
        with self.assertRaisesRegex(ValueError, "CT volume"):
            self.build(nodes=dict(allNodes(), inputVolume=None))

    def test_EmptyOrMissingSeed_IsLeftOutForTheAutomaticSeed(self):
        # Issue 16 item 1: without a seed the CLI finds the aorta itself.
        for nodes, counts in ((allNodes(), {"seed": 0}), (dict(allNodes(), seed=None), {"seed": 1})):
            self.assertNotIn("seed", self.build(nodes=nodes, counts=counts))
        self.assertIn("seed", self.build())

    def test_MissingOutputNode_IsAValueError(self):
        with self.assertRaisesRegex(ValueError, "outputMeasurements"):
            self.build(nodes=dict(allNodes(), outputMeasurements=None))

    def test_InvalidSettings_AreRejectedBeforeAnythingElse(self):
        settings = dict(Settings.defaultSettings(), oversizingMinPercent=30.0)
        with self.assertRaises(ValueError):
            self.build(settings)


class OutputNodesTest(unittest.TestCase):
    """Issue 33 item 7: settings are checked before the output nodes are created."""

    def inputs(self):
        return {role.name: Node(role.name) for role in Settings.NODE_ROLES if role.channel == "input"}

    def run_(self, settings, inputs):
        created = []

        def outputNode(role):
            created.append(role.name)
            return Node(role.name)

        parameters = Settings.cliParametersCreatingOutputs(settings, inputs, ONE_POINT, outputNode, "/tmp/r.json")
        return parameters, created

    def test_ValidSettings_CreateEveryOutputOnceAndPassItToTheCli(self):
        parameters, created = self.run_(Settings.defaultSettings(), self.inputs())
        self.assertEqual(created, [role.name for role in Settings.OUTPUT_ROLES])
        for name in created:
            self.assertEqual(parameters[name].name, name)

    def test_InvalidSettingsOrNoVolume_CreateNoNode(self):
        cases = (
            (dict(Settings.defaultSettings(), oversizingMinPercent=30.0), self.inputs()),
            (dict(Settings.defaultSettings(), thresholdMode="manual", lowerHu=700.0), self.inputs()),
            (dict(Settings.defaultSettings(), deviceFamily="Endurant:II"), self.inputs()),
            (Settings.defaultSettings(), dict(self.inputs(), inputVolume=None)),
        )
        for settings, inputs in cases:
            created = []
            with self.assertRaises(ValueError):
                Settings.cliParametersCreatingOutputs(settings, inputs, ONE_POINT,
                                                      lambda role: created.append(role) or Node(role.name),
                                                      "/tmp/r.json")
            self.assertEqual(created, [])


if __name__ == "__main__":
    unittest.main()
