# Core tests.
