# make        set up .venv (pinned) and build everything with Snakemake
# make test   set up .venv (pinned) and run the test suite
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
CORES ?= all

.PHONY: all setup test lint bench lock clean

all: $(STAMP)
	@if [ -f Snakefile ]; then $(BIN)/snakemake --cores $(CORES); \
	else echo "set-up done (no pipeline yet)"; fi

setup: $(STAMP)

$(STAMP): pyproject.toml constraints.txt
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	PIP_CONSTRAINT=constraints.txt $(BIN)/python -m pip install --quiet \
		--disable-pip-version-check -e ".[test,dev,notebooks]"
	touch $(STAMP)

test: $(STAMP)
	$(BIN)/python -m pytest -n 2

lint: $(STAMP)
	$(BIN)/ruff check src tests benchmarks scripts
	$(BIN)/ruff format --check src tests benchmarks scripts

bench: $(STAMP)
	$(BIN)/python benchmarks/run.py

# Re-resolve the newest versions into constraints.txt (needs the network).
lock:
	rm -rf .lockvenv && $(PYTHON) -m venv .lockvenv
	.lockvenv/bin/pip install --quiet ".[test,dev,notebooks,slurm]"
	{ echo "# Exact versions of every package the project installs (pip constraints)."; \
	  echo "# Regenerate: make lock"; \
	  .lockvenv/bin/pip freeze --all --exclude-editable | grep -v -e '^turntable' -e '^pip=='; } > constraints.txt
	rm -rf .lockvenv

clean:
	rm -rf figures results logs .snakemake paper/paper.pdf
