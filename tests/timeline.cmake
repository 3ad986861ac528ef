# Timeline tests.
