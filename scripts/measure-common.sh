# Sourced by the measure-*.sh scripts, from the repository root: ML is the binary to measure
# (built here when not given, so that `ML=/path/to/other/build/manylights` measures another
# build), and the machine and its load are printed first, so that every figure a script prints
# states where it was taken.
if [ -z "${ML:-}" ]; then
  make build >/dev/null
  ML=build/manylights
fi
echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg), binary $ML"
