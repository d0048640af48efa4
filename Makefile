# make        set up .venv (pinned) and build everything with Snakemake
# make test   set up .venv (pinned) and run the test suite
# make docs   the documentation site, docs/_build/html/index.html
# make notebooks / make report / make readme-figure   see the documentation
# make CONFIGFILE=my.yaml   build with the values of my.yaml over config/config.yaml
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
# Two stages of .venv: what the build needs (make), then the tools of the tests and of
# development (make setup, make test, make lint). pip installs uv (pinned in constraints.txt)
# into .venv, and uv the pinned set: seconds, not minutes. Without byte-compiling every
# installed file (7000 files, 25 s of CPU; uv does not unless asked): Python compiles, and
# caches, a module when it is first imported (the first build writes the caches of the 2300
# it imports, about 15 s of CPU). An environment with PYTHONDONTWRITEBYTECODE set would keep
# Python from writing them, and every run would compile every module again (a no-op
# snakemake 2.4 s instead of 1 s): make does not pass it on.
unexport PYTHONDONTWRITEBYTECODE
BUILD_STAMP := $(VENV)/.installed-build
STAMP := $(VENV)/.installed
DOCS_STAMP := $(VENV)/.installed-docs
NOTEBOOKS_STAMP := $(VENV)/.installed-notebooks
UV := $(BIN)/uv
UV_INSTALL := $(UV) pip install --quiet --python $(BIN)/python --constraints constraints.txt
CORES ?= all

# With CONFIGFILE, the file is read first: Snakemake answers a missing file with a traceback
# and a YAML syntax error without its line.
READ_CONFIG = $(BIN)/python -c 'import sys, yaml; sys.excepthook = lambda t, e, tb: print(f"{sys.argv[1]}: {e}", file=sys.stderr); yaml.safe_load(open(sys.argv[1]))'
SNAKEMAKE = $(if $(CONFIGFILE),$(READ_CONFIG) $(CONFIGFILE) && )$(BIN)/snakemake$(if $(CONFIGFILE), --configfile $(CONFIGFILE))

.PHONY: all setup test test-slow lint bench mutants lock clean notebooks report readme-figure docs \
	cluster-test

# The HTML report is rewritten only when a file it is made from is newer than it (an output
# it shows, a caption of workflow/report/, a rule or script, the configuration), so that a second
# `make` does nothing. (results/benchmarks.json, which .ci/run writes after make, is not in it.)
REPORT := if [ ! -f results/report.html ] || [ -n "$$(find figures results workflow scripts config \
	-newer results/report.html ! -path results/report.html ! -path results/benchmarks.json \
	! -path "*/__pycache__/*" -type f -print -quit 2>/dev/null)" ]; then \
	$(SNAKEMAKE) --report results/report.html; else echo "results/report.html is up to date"; fi

all: $(BUILD_STAMP)
	$(SNAKEMAKE) --cores $(CORES)
	@$(REPORT)
	@$(BIN)/python tools/build_summary.py

# Every script of scripts/ executed as a notebook with its outputs: results/notebooks/ (not
# part of make, whose outputs depend on no notebook).
notebooks: $(NOTEBOOKS_STAMP)
	$(SNAKEMAKE) --cores $(CORES) notebooks

# Self-contained HTML page with every figure and its caption (needs the built figures).
report: $(BUILD_STAMP)
	$(SNAKEMAKE) --cores $(CORES)
	@$(REPORT)

# Refresh the figure and the animation shown in README.md (docs/fig4_trajectories.png,
# docs/animation.gif).
readme-figure: $(BUILD_STAMP)
	$(SNAKEMAKE) --cores $(CORES) readme_figure

setup: $(STAMP) $(DOCS_STAMP)

$(UV): constraints.txt
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check --constraint constraints.txt uv
	touch $(UV)

$(BUILD_STAMP): pyproject.toml constraints.txt $(UV)
	$(UV_INSTALL) -e ".[workflow,video,cli]"
	touch $(BUILD_STAMP)

$(NOTEBOOKS_STAMP): $(BUILD_STAMP)
	$(UV_INSTALL) -e ".[workflow,notebooks,video,cli]"
	touch $(NOTEBOOKS_STAMP)

$(STAMP): $(BUILD_STAMP)
	$(UV_INSTALL) -e ".[workflow,test,dev,notebooks,video,cli]"
	touch $(STAMP)

$(DOCS_STAMP): $(BUILD_STAMP)
	$(UV_INSTALL) -e ".[workflow,docs,cli]"
	touch $(DOCS_STAMP)

test: $(STAMP)
	$(BIN)/python -m pytest -n 2

# The tests marked slow (the shared build of the workflow and every test that reads it, the
# coverage campaigns of the fit, videos rendered and tracked for seconds each, a dry run of the
# whole workflow, a Jupyter kernel, or the wheel installed in a fresh venv): run by CI.
test-slow: $(STAMP)
	$(BIN)/python -m pytest -n 2 -m slow

# The documentation site from docs/ (guides, the API reference and the executed notebooks),
# offline; a warning fails it. Built beside the site, which it replaces only when it builds: no
# page outlives its source.
docs: $(DOCS_STAMP) notebooks
	rm -rf docs/_build/html.new
	$(BIN)/sphinx-build -b html docs docs/_build/html.new -d docs/_build/doctrees -E -W \
		--keep-going -q
	rm -rf docs/_build/html && mv docs/_build/html.new docs/_build/html

lint: $(STAMP)
	$(BIN)/ruff check src tests benchmarks scripts workflow tools
	$(BIN)/ruff format --check src tests benchmarks scripts workflow tools
	$(BIN)/snakefmt --check .
	$(BIN)/snakemake --lint

# Break the physics on purpose (a sign in L, k/(k+1), the sign in y0, ...) and check
# that the test suite catches every such mutant.
mutants: $(STAMP)
	$(BIN)/python tools/mutants.py

# benchmarks/video.py also renders with MuJoCo (the extra [bench]; offscreen through EGL).
bench: $(STAMP)
	$(UV_INSTALL) -e ".[bench]"
	$(BIN)/python benchmarks/run.py
	$(BIN)/python benchmarks/pipeline.py

# The workflow on a real SLURM cluster of one node, started here and stopped after (as root:
# installs Debian's slurm-wlm and munge when missing). See tools/cluster_test.py.
cluster-test: $(STAMP)
	command -v slurmctld >/dev/null || { apt-get install -y -q slurm-wlm munge || \
		{ apt-get update -q && apt-get install -y -q slurm-wlm munge; }; }
	$(UV_INSTALL) -e ".[slurm]"
	$(BIN)/python tools/cluster_test.py

# Re-resolve the newest versions of the package, every extra, uv and the build's setuptools
# and wheel into constraints.txt, for every platform (uv pip compile installs nothing;
# needs the network). LOCK_FLAGS= keeps the versions already pinned where they still fit.
LOCK_FLAGS ?= --upgrade
lock: $(UV)
	printf 'uv\nsetuptools\nwheel\n' | $(UV) pip compile pyproject.toml - --all-extras \
		--universal --python-version 3.11 --no-header --no-annotate --quiet $(LOCK_FLAGS) \
		--output-file constraints.txt
	{ echo "# Exact versions of every package the project installs (pip and uv constraints)."; \
	  echo "# Regenerate: make lock"; grep -v '^#' constraints.txt; } > constraints.txt.new
	mv constraints.txt.new constraints.txt

clean:
	rm -rf figures results logs .snakemake paper/paper.pdf docs/_build
