"""Prints how many cases of the conformance table ran through Python and through the FMUs."""


def pytest_terminal_summary(terminalreporter):
    from test_conformance import RAN

    terminalreporter.write_line(f"conformance: {RAN['python']} cases through Python, {RAN['fmu']} through the FMUs")
