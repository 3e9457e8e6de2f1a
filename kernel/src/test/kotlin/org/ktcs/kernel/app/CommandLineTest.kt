package org.ktcs.kernel.app

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withData
import io.kotest.matchers.shouldBe
import org.ktcs.kernel.bench.BenchOptions
import org.ktcs.kernel.bench.ClientKind
import org.ktcs.kernel.bench.Workload
import java.nio.file.Path

class CommandLineTest : FunSpec({
    test("no arguments start the kernel with the demo plant") {
        CommandLine.parse(emptyList()) shouldBe Command.Run(RunOptions())
    }

    test("run options in both spellings, --set repeatable") {
        CommandLine.parse(
            listOf("--model", "a.xml", "--config=b.conf", "--set", "web.port=1", "--set=xml.orders.port=2"),
        ) shouldBe
            Command.Run(RunOptions(Path.of("a.xml"), Path.of("b.conf"), listOf("web.port=1", "xml.orders.port=2")))
    }

    test("config commands") {
        CommandLine.parse(listOf("config", "defaults")) shouldBe Command.ConfigTemplate
        CommandLine.parse(listOf("config", "reference")) shouldBe Command.ConfigReference
        CommandLine.parse(listOf("config", "--set", "web.port=1")) shouldBe
            Command.ShowConfig(RunOptions(overrides = listOf("web.port=1")))
    }

    test("model tools") {
        CommandLine.parse(listOf("model", "check", "m.xml")) shouldBe Command.CheckModel(Path.of("m.xml"))
        CommandLine.parse(listOf("model", "convert", "in.xml", "out.xml")) shouldBe
            Command.ConvertModel(Path.of("in.xml"), Path.of("out.xml"))
        CommandLine.parse(listOf("model", "generate", "grid", "20x20", "--vehicles", "30", "g.xml")) shouldBe
            Command.GenerateModel(GeneratedPlant("grid", 20, 20, 30), Path.of("g.xml"))
        CommandLine.parse(listOf("model", "generate", "warehouse", "8x12", "w.xml")) shouldBe
            Command.GenerateModel(GeneratedPlant("warehouse", 8, 12, 10), Path.of("w.xml"))
    }

    test("simulate on a generated grid, on the wall clock with a time factor") {
        CommandLine.parse(listOf("simulate", "--grid", "10x10", "--real-time", "--time-factor", "100")) shouldBe
            Command.Simulate(SimulateOptions(grid = 10 to 10, realTime = true, timeFactor = 100.0))
    }

    test("bench: a workload and its options") {
        CommandLine.parse(listOf("bench")) shouldBe Command.Bench(BenchOptions())
        CommandLine.parse(listOf("bench", "batch", "--grid", "10x10", "--vehicles", "10", "--orders=50")) shouldBe
            Command.Bench(BenchOptions(workload = Workload.BATCH, grid = 10 to 10, vehicles = 10, orders = 50))
        CommandLine.parse(
            listOf("bench", "demo", "--runs", "3", "--cpu-batches", "5,20", "--time-factor", "10"),
        ) shouldBe
            Command.Bench(BenchOptions(runs = 3, cpuBatches = listOf(5, 20), timeFactor = 10.0))
        CommandLine.parse(listOf("bench", "soak", "--hours", "24", "--minutes", "30", "--keep-hours=2")) shouldBe
            Command.Bench(BenchOptions(workload = Workload.SOAK, soakHours = 24.0, soakMinutes = 30.0, keepHours = 2.0))
        CommandLine.parse(listOf("bench", "--client", "raw")) shouldBe
            Command.Bench(BenchOptions(clientKinds = listOf(ClientKind.RAW)))
        CommandLine.parse(listOf("bench", "--help")) shouldBe Command.BenchHelp
    }

    context("mistakes get a one-line message") {
        withData(
            listOf("--modle", "x") to "unknown option '--modle'",
            listOf("--model") to "--model needs a value",
            listOf("model") to "'model' needs a subcommand: check, convert or generate",
            listOf("model", "fix", "x") to "unknown model subcommand 'fix': expected check, convert or generate",
            listOf("model", "generate", "maze", "9x9", "o.xml") to
                "unknown plant kind 'maze': expected grid or warehouse",
            listOf("model", "generate", "grid", "2x9", "o.xml") to
                "model generate expects WIDTHxHEIGHT with both at least 3, e.g. 40x40, got '2x9'",
            listOf("simulate", "--grid", "9x9", "--warehouse", "9x9") to
                "give only one of --model, --grid and --warehouse",
            listOf("simulate", "--time-factor", "0") to "--time-factor expects a positive number",
            listOf("model", "check") to "expected 'model check FILE', got 0 argument(s)",
            listOf("model", "convert", "a") to "expected 'model convert IN OUT', got 1 argument(s)",
            listOf("simulate2") to "unknown command 'simulate2'",
            listOf("bench", "--runs", "0") to "--runs expects a positive whole number, got '0'",
            listOf("bench", "--model", "a.xml", "--grid", "5x5") to "give either --model or --grid, not both",
            listOf("bench", "soak", "--minutes", "0") to "--minutes expects a positive number, got '0'",
            listOf("bench", "soak", "--url", "http://127.0.0.1:55200") to
                "bench soak starts its own kTCS; not with --url",
            listOf("bench", "--client", "curl") to "--client expects jdk, raw or both separated by a comma, got 'curl'",
            listOf("bench", "--url", "https://h:1") to
                "the raw client speaks plain HTTP: with an https --url give --client jdk",
            listOf("bench", "--speed", "1") to "unknown bench option '--speed' (ktcs bench --help lists them)",
        ) { (args, message) ->
            shouldThrow<UsageException> { CommandLine.parse(args) }.message shouldBe message
        }
    }
})
