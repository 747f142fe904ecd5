# One case file per case and per dried state; dry once, compress every case from its dried state.

wildcard_constraints:
    case="[A-Za-z0-9_.+-]+",
    dried="[A-Za-z0-9_.+-]+",


# The JSON is made here, when the workflow is parsed, and written by the shell: no Python process
# per file (a `script:` job spends most of a second importing Snakemake). A changed case changes the
# rule's params, which makes Snakemake write the file again.
rule case_file:
    output:
        f"{OUT}/cases/{{case}}.json",
    params:
        json=lambda w: matrix.case_json(CASES[w.case].case),
    shell:
        "printf '%s' {params.json:q} > {output:q}"


rule dried_case_file:
    output:
        f"{OUT}/cases/dried/{{dried}}.json",
    params:
        json=lambda w: matrix.case_json(DRIED[w.dried]),
    shell:
        "printf '%s' {params.json:q} > {output:q}"


rule dry:
    input:
        exe=SOLVER,
        case=f"{OUT}/cases/dried/{{dried}}.json",
    output:
        h5=f"{OUT}/runs/dried/{{dried}}.h5",
        wall=f"{OUT}/runs/dried/{{dried}}.wall.xdmf",
        fluid=f"{OUT}/runs/dried/{{dried}}.fluid.xdmf",
    log:
        f"{OUT}/logs/dry/{{dried}}.log",
    threads: lambda w: run_resources("dry", DRIED[w.dried], "threads", 1)
    resources:
        mem_mb=lambda w: run_resources("dry", DRIED[w.dried], "mem_mb", 1000),
        runtime=lambda w: run_resources("dry", DRIED[w.dried], "runtime_min", 30),
    shell:
        "{input.exe:q} run {input.case:q} --set compression.steps=0 --threads {threads} -o {output.h5:q} > {log:q} 2>&1"


rule compress:
    input:
        exe=SOLVER,
        case=f"{OUT}/cases/{{case}}.json",
        dried=lambda w: dried_file(CASES[w.case].dried),
    output:
        h5=f"{OUT}/runs/{{case}}.h5",
        wall=f"{OUT}/runs/{{case}}.wall.xdmf",
        fluid=f"{OUT}/runs/{{case}}.fluid.xdmf",
    log:
        f"{OUT}/logs/compress/{{case}}.log",
    threads: lambda w: run_resources("compress", CASES[w.case].case, "threads", 1)
    resources:
        mem_mb=lambda w: run_resources("compress", CASES[w.case].case, "mem_mb", 1000),
        runtime=lambda w: run_resources("compress", CASES[w.case].case, "runtime_min", 20),
    shell:
        "{input.exe:q} run {input.case:q} --from {input.dried:q} --threads {threads} -o {output.h5:q} > {log:q} 2>&1"
