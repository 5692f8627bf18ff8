"""The table of numeric OpenSCENARIO attributes is the ASAM XSDs' own, and it is applied."""

from __future__ import annotations

import pytest

from vei_scenario.openscenario.numeric_attributes import numeric_table, table_from_xsd


def test_numeric_table_equals_the_xsds():
    from vei_scenario.openscenario.asam_schemas import OSC_PACKAGE, OSC_SCHEMAS, schema_dir

    base = schema_dir(OSC_PACKAGE)
    if base is None:
        pytest.skip("ASAM XSDs not installed")
    assert table_from_xsd([base / rel for rel in OSC_SCHEMAS.values()]) == numeric_table()


def test_table_knows_the_quantities_that_matter():
    t = numeric_table()
    assert t["Dimensions"] == {"height": "double", "length": "double", "width": "double"}
    assert t["AbsoluteTargetSpeed"]["value"] == "double"
    assert t["Event"]["maximumExecutionCount"] == "unsignedInt"
    assert "name" not in t.get("ParameterDeclaration", {})  # strings stay strings
