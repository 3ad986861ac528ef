# Placeholder until shaders are embedded.
set(TL_EMBEDDED_SHADERS_C)
