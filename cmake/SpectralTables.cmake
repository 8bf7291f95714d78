# Generated spectral tables. Filled in by the spectral core (rgb-to-spectrum coefficients).
set(CAUSTICA_GENERATED_SOURCES)
add_custom_target(caustica_generated_tables)
