package robotworld.explorer.monitor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import robotworld.observe.AnswerSeen;
import robotworld.observe.ModuleRef;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldObserver;

/**
 * The numbers a world's modules report, over time, for the plots: per module one {@link TimeSeries} per channel
 * ({@link NumericChannels}) and one for the latency of its calls (milliseconds, where known). Every series is a
 * fixed-size ring, and there is one series per channel of a known module, so memory stays bounded however long
 * the monitor runs. Times are seconds since the model was made. Fed by a {@link robotworld.observe.WorldTap};
 * read from any thread.
 */
public final class PlotModel implements WorldObserver {

    /** The span the plots show. */
    public static final double WINDOW_SECONDS = 60;
    /** Points per series: 60 s at 50 values a second, with room to spare. */
    public static final int CAPACITY = 4096;
    /** The highest channel number kept (modules have at most 8). */
    static final int MAX_CHANNEL = 16;

    private final long origin = System.nanoTime();
    private final Map<ModuleRef, ModuleSeries> modules = new LinkedHashMap<>();

    /** The modules of {@code layout}, in its order. */
    public PlotModel(WorldLayout layout) {
        for (ModuleRef module : layout.modules()) {
            modules.put(module, new ModuleSeries(module));
        }
    }

    /** The series of one module. */
    public static final class ModuleSeries {
        private final ModuleRef module;
        private final Map<Integer, TimeSeries> channels = new ConcurrentHashMap<>();
        private final TimeSeries latency = new TimeSeries(CAPACITY);
        private final LampLevel lamp = new LampLevel();

        ModuleSeries(ModuleRef module) {
            this.module = module;
        }

        /** The module. */
        public ModuleRef module() {
            return module;
        }

        /** Channel number to its series, in channel order (channels appear as they first report). */
        public Map<Integer, TimeSeries> channels() {
            return new TreeMap<>(channels);
        }

        /** The latency of its calls in milliseconds, where the tap knew it. */
        public TimeSeries latency() {
            return latency;
        }
    }

    /** Every module's series, in layout order. */
    public List<ModuleSeries> modules() {
        return new ArrayList<>(modules.values());
    }

    /** The series of {@code module}, or null when it is not in the layout. */
    public ModuleSeries of(ModuleRef module) {
        return modules.get(module);
    }

    /** Seconds since the model was made: the time axis. */
    public double now() {
        return (System.nanoTime() - origin) / 1e9;
    }

    /** Points held by all series together (bounded by the number of series times {@link #CAPACITY}). */
    public long pointsHeld() {
        long points = 0;
        for (ModuleSeries series : modules.values()) {
            points += series.latency.size();
            for (TimeSeries channel : series.channels.values()) {
                points += channel.size();
            }
        }
        return points;
    }

    @Override
    public void answerSeen(AnswerSeen event) {
        ModuleSeries series = modules.get(event.module());
        if (series == null) {
            return;
        }
        double time = event.earlier() ? 0 : now();
        for (NumericChannels.Sample sample : NumericChannels.of(event.module().moduleClass(), event.answer(),
                series.lamp)) {
            if (sample.number() < 0 || sample.number() > MAX_CHANNEL) {
                continue; // a malformed answer must not grow the model
            }
            series.channels.computeIfAbsent(sample.number(), number -> new TimeSeries(CAPACITY))
                    .add(time, sample.value());
        }
        if (event.latency() != null) {
            series.latency.add(time, event.latency().toNanos() / 1e6);
        }
    }
}
