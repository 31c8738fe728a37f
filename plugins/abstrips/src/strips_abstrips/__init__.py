"""ABSTRIPS (Sacerdoti 1974): STRIPS planning in a hierarchy of abstraction spaces."""
