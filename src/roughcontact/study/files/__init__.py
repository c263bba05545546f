"""The study's files: the run file's data model, reading and writing, provenance and logs."""
