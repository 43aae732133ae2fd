"""What the panel shows once a planning run has ended, without Slicer.

``planningResults`` turns what a completed run left behind (the JSON report's text, the return
parameters through ``getParameterAsString``, the measurements table's rows) into
``PlanningResults``: the values, the parsed report, the panel table's rows and the panel's text
(the order list beside the anatomy, then the recommendation, the IFU details, the fit check, or
the reason no graft was simulated). A run whose device selection found nothing is a completed run
like any other (the CLI exits 0 and writes every output: an empty simulated model among them);
its text says why no device fits.

How the run ended (completed, cancelled, failed) and the status line are CliRun's
(``runOutcome``, ``finishedMessage``).
"""

from . import OrderList, Results


class PlanningResults:
    """What a finished run returned: return values, the parsed report, the results table's rows
    (label, value text, wall, estimated) and the panel text as rich text for QLabels; the visual
    report's path, when the run wrote one; for a re-plan, what changed (changesHtml, set by the
    panel's logic from Replan.replanHtml; "" for a plan)."""

    def __init__(self, values, report, measurementRows, reportHtmlPath=None):
        self.values = values
        self.report = report
        self.reportHtmlPath = reportHtmlPath
        self.tableRows = Results.resultsTableRows(values, measurementRows)
        self.orderListHtml = OrderList.orderListHtml(report, values)
        self.recommendationHtml = Results.recommendationHtml(report)
        self.changesHtml = ""


def planningResults(reportText, getParameterAsString, measurementRows, reportHtmlPath=None):
    """PlanningResults of a completed run.

    reportText: the JSON report the CLI wrote (Results.parseReport's ValueError when it is not one).
    getParameterAsString: name -> text of a return parameter (the CLI node's method, or a reader of
        the return-parameter file).
    measurementRows: the measurements table's rows, as dicts column name -> text.
    reportHtmlPath: the visual report's path when it was written, else None.
    """
    report = Results.parseReport(reportText)
    values = Results.withReportVerdicts(Results.readReturnValues(getParameterAsString), report)
    return PlanningResults(values, report, measurementRows, reportHtmlPath)
