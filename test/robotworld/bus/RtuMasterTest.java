package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import robotworld.bus.modbus.Pdus;
import robotworld.bus.modbus.RtuFrame;
import robotworld.bus.modbus.RtuTiming;

/** The master's handling of replies at byte level: retries, stray frames, exceptions, quiet calls, link loss. */
class RtuMasterTest {

    private static final RtuMaster.CallPolicy POLICY = new RtuMaster.CallPolicy(Duration.ofMillis(40), 3, true);
    private static final byte[] READ_BUMPERS = Pdus.readDiscreteInputs(0, 8);
    private static final byte[] BUMPERS_REPLY = HexFormat.of().parseHex("020128");

    private final List<RtuFrame> strays = new ArrayList<>();

    private RtuMaster master(ScriptedBusLink link) {
        BusTiming timing = BusTiming.defaults().withFrameGap(Duration.ZERO);
        RtuMaster master = new RtuMaster(link, RtuTiming.of(115_200, 86_806), timing,
                address -> "BumperModule 'Front' at address " + address);
        master.onStrayFrame(strays::add);
        link.open();
        return master;
    }

    private static byte[] frame(int address, byte[] pdu) {
        return new RtuFrame(address, pdu).encode();
    }

    private static byte[] corrupted(byte[] frame) {
        byte[] copy = frame.clone();
        copy[copy.length - 1] ^= 0x5A;
        return copy;
    }

    /** Answers the first {@code bad} requests with {@code badReply}, then correctly. */
    private static Function<byte[], List<byte[]>> badThenGood(int bad, Function<byte[], byte[]> badReply) {
        AtomicInteger calls = new AtomicInteger();
        return request -> {
            byte[] good = frame(request[0], BUMPERS_REPLY);
            return List.of(calls.getAndIncrement() < bad ? badReply.apply(good) : good);
        };
    }

    @Test
    void aCorruptedReplyIsRetried() {
        ScriptedBusLink link = new ScriptedBusLink(badThenGood(2, RtuMasterTest::corrupted));
        RtuMaster master = master(link);
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        BusStatistics statistics = master.statistics();
        assertEquals(3, statistics.transactions());
        assertEquals(2, statistics.retries());
        assertEquals(2, statistics.crcErrors());
    }

    @Test
    void onlyCorruptedRepliesEndInACrcErrorNamingTheModule() {
        ScriptedBusLink link = new ScriptedBusLink(badThenGood(99, RtuMasterTest::corrupted));
        BusCrcException e = assertThrows(BusCrcException.class, () -> master(link).call(2, READ_BUMPERS, POLICY));
        assertEquals(2, e.address());
        assertTrue(e.getMessage().contains("BumperModule 'Front' at address 2 on script://bus"), e.getMessage());
        assertTrue(e.getMessage().contains("3 attempts"), e.getMessage());
    }

    @Test
    void aReplyCutShortCountsAsCorruptedAndIsRetried() {
        ScriptedBusLink link = new ScriptedBusLink(badThenGood(1, good -> java.util.Arrays.copyOf(good, 4)));
        RtuMaster master = master(link);
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        assertEquals(1, master.statistics().crcErrors());
    }

    @Test
    void silenceIsATimeoutAfterEveryAttempt() {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of());
        RtuMaster master = master(link);
        BusTimeoutException e = assertThrows(BusTimeoutException.class, () -> master.call(7, READ_BUMPERS, POLICY));
        assertTrue(e.getMessage().contains("address 7"), e.getMessage());
        assertTrue(e.getMessage().contains("no reply to read discrete inputs (0x02) within 40 ms (3 attempts)"),
                e.getMessage());
        assertEquals(3, link.written().size());
    }

    @Test
    void aLineSilentForSeveralCallsIsOpenedAgainButOneAbsentModuleIsNot() {
        // only address 2 answers: calls to an absent address 7 between answered ones never reopen the link
        ScriptedBusLink link = new ScriptedBusLink(request -> request[0] == 2
                ? List.of(frame(2, BUMPERS_REPLY)) : List.of());
        RtuMaster master = master(link);
        master.reopenForSilence(true); // as for a tcp:// link
        RtuMaster.CallPolicy once = new RtuMaster.CallPolicy(Duration.ofMillis(5), 1, true);
        for (int i = 0; i < 2 * RtuMaster.SILENT_CALLS_BEFORE_REOPEN; i++) {
            assertThrows(BusTimeoutException.class, () -> master.call(7, READ_BUMPERS, once));
            assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, once));
        }
        assertEquals(1, link.opens(), "a line that answers is not opened again");

        // the whole line falls silent: after SILENT_CALLS_BEFORE_REOPEN calls it is opened again
        link.respondWith(request -> List.of());
        for (int i = 0; i < RtuMaster.SILENT_CALLS_BEFORE_REOPEN; i++) {
            assertThrows(BusTimeoutException.class, () -> master.call(2, READ_BUMPERS, once));
        }
        assertEquals(1, link.opens(), "not before the next request");
        link.respondWith(request -> List.of(frame(2, BUMPERS_REPLY)));
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        assertEquals(2, link.opens());

        // a scan's silences do not count
        link.respondWith(request -> List.of());
        RtuMaster.CallPolicy scan = new RtuMaster.CallPolicy(Duration.ofMillis(5), 1, false);
        for (int address = 10; address < 10 + 2 * RtuMaster.SILENT_CALLS_BEFORE_REOPEN; address++) {
            int asked = address;
            assertThrows(BusTimeoutException.class, () -> master.call(asked, READ_BUMPERS, scan));
        }
        link.respondWith(request -> List.of(frame(request[0], BUMPERS_REPLY)));
        assertArrayEquals(BUMPERS_REPLY, master.call(30, READ_BUMPERS, POLICY));
        assertEquals(2, link.opens());
    }

    @Test
    void aScanDoesNotRetrySilence() {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of());
        RtuMaster master = master(link);
        RtuMaster.CallPolicy scan = new RtuMaster.CallPolicy(Duration.ofMillis(5), 3, false);
        assertThrows(BusTimeoutException.class, () -> master.call(7, READ_BUMPERS, scan));
        assertEquals(1, link.written().size());
    }

    @Test
    void aLateReplyFromAnotherAddressIsAStrayFrameNotTheAnswer() {
        byte[] late = frame(5, BUMPERS_REPLY);
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(late, frame(request[0], HexFormat.of()
                .parseHex("020101"))));
        RtuMaster master = master(link);
        assertArrayEquals(HexFormat.of().parseHex("020101"), master.call(2, READ_BUMPERS, POLICY));
        assertEquals(List.of(RtuFrame.decode(late, late.length)), strays);
    }

    @Test
    void bytesWaitingBeforeARequestAreDrainedAndReportedWhenTheyAreAFrame() {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(frame(request[0], BUMPERS_REPLY)));
        RtuMaster master = master(link);
        link.inject(frame(9, BUMPERS_REPLY));
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        assertEquals(9, strays.get(0).address());
        link.inject(new byte[] {1, 2, 3});
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        assertEquals(1, strays.size(), "noise is dropped, not reported");
    }

    @Test
    void anExceptionResponseIsNotRetried() {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(frame(request[0], new byte[] {(byte) 0x82, 2})));
        RtuMaster master = master(link);
        ModuleRefusedException e = assertThrows(ModuleRefusedException.class,
                () -> master.call(2, READ_BUMPERS, POLICY));
        assertEquals(2, e.exceptionCode());
        assertEquals(0x02, e.functionCode());
        assertTrue(e.getMessage().contains("Modbus exception 2 (illegal data address)"), e.getMessage());
        assertEquals(1, link.written().size());
        assertEquals(1, master.statistics().exceptionResponses());
    }

    @Test
    void aReplyWithTheWrongFunctionIsAProtocolError() {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(frame(request[0], HexFormat.of()
                .parseHex("0302FFFF"))));
        BusProtocolException e = assertThrows(BusProtocolException.class,
                () -> master(link).call(2, READ_BUMPERS, POLICY));
        assertTrue(e.getMessage().contains("unexpected reply"), e.getMessage());
    }

    @Test
    void aReplyInPiecesIsAssembled() {
        ScriptedBusLink link = new ScriptedBusLink(request -> {
            byte[] whole = frame(request[0], BUMPERS_REPLY);
            return List.of(java.util.Arrays.copyOf(whole, 2), java.util.Arrays.copyOfRange(whole, 2, whole.length));
        });
        assertArrayEquals(BUMPERS_REPLY, master(link).call(2, READ_BUMPERS, POLICY));
    }

    @Test
    void aQuietCallReturnsAtOnceAndItsReplyIsConsumedBeforeTheNextCall() {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(request.clone()));
        RtuMaster master = master(link);
        byte[] write = Pdus.writeSingleRegister(0, 500);
        master.callQuietly(1, write, Duration.ofMillis(40));
        assertEquals(1, link.written().size());
        link.respondWith(request -> List.of(frame(request[0], BUMPERS_REPLY)));
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        assertTrue(strays.isEmpty(), "the quiet call's confirmation is not taken for a stray frame");
    }

    @Test
    void aQuietCallsReplyThatCameInTimeCountsThoughTheNextCallComesAfterItsTimeout() throws InterruptedException {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(request.clone())); // confirmed at once
        RtuMaster master = master(link);
        master.callQuietly(1, Pdus.writeSingleRegister(0, 500), Duration.ofMillis(10));
        Thread.sleep(50); // the caller is busy elsewhere (or the machine is): the confirmation waits in the buffer
        link.respondWith(request -> List.of(frame(request[0], BUMPERS_REPLY)));
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        assertEquals(0, master.statistics().timeouts(), "the confirmation came in time");
        assertTrue(strays.isEmpty(), "and is not taken for a stray frame");
    }

    @Test
    void aQuietCallWithoutConfirmationDoesNotDisturbTheNextCall() {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of());
        RtuMaster master = master(link);
        master.callQuietly(1, Pdus.writeSingleRegister(0, 500), Duration.ofMillis(10));
        link.respondWith(request -> List.of(frame(request[0], BUMPERS_REPLY)));
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        assertEquals(1, master.statistics().timeouts());
    }

    @Test
    void aLostLinkFailsTheCallAndIsReopenedForTheNext() {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(frame(request[0], BUMPERS_REPLY)));
        RtuMaster master = master(link);
        link.failNextWrite();
        BusException e = assertThrows(BusException.class, () -> master.call(2, READ_BUMPERS, POLICY));
        assertTrue(e.getMessage().contains("the link failed"), e.getMessage());
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        assertEquals(2, link.opens());
    }

    // ----- late replies from the address asked (a reply after its request timed out) -----

    /** One attempt, 40 ms: the late-reply window is 4 x the bus's 100 ms reply timeout = 400 ms. */
    private static final RtuMaster.CallPolicy ONCE = new RtuMaster.CallPolicy(Duration.ofMillis(40), 1, true);

    @Test
    void aLateReplyToATimedOutRequestIsDiscardedNotTakenForTheNextAnswer() {
        // a slow module that answers in order: "bumper 4 has contact" (02 01 01) comes after the master has given up
        // on that request; reading all eight bumpers asks the same address the same shape
        byte[] readBumper4 = Pdus.readDiscreteInputs(3, 1);
        ScriptedBusLink link = new ScriptedBusLink(request -> request[3] == 3 ? List.of()
                : List.of(frame(2, BUMPERS_REPLY)));
        RtuMaster master = master(link);
        assertThrows(BusTimeoutException.class, () -> master.call(2, readBumper4, ONCE));
        link.inject(frame(2, HexFormat.of().parseHex("020101"))); // late: the master gave up on it
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, ONCE),
                "the mask 0x28, not the late single-bumper reply 02 01 01");
        assertEquals(1, master.statistics().staleReplies());
        assertEquals(0, master.statistics().strayFrames());
        // not an answer, but proof that address 2 is there: the listener (bus exploration) hears of it
        assertEquals(List.of(2), strays.stream().map(RtuFrame::address).toList(), "the stale reply was heard");
        assertEquals(2, link.written().size());
    }

    @Test
    void aWriteConfirmationLaterThanTheWindowNeverConfirmsTheNextWrite() {
        // the motor's "speed -400" confirmation was not heard in time; it comes only after the late-reply window,
        // just before the confirmation of "speed 400": the bytes tell them apart, however late the first comes
        byte[] slower = Pdus.writeSingleRegister(1, 0xFE70);
        byte[] faster = Pdus.writeSingleRegister(1, 400);
        AtomicInteger writes = new AtomicInteger();
        ScriptedBusLink link = new ScriptedBusLink(request -> writes.getAndIncrement() == 0 ? List.of()
                : List.of(frame(1, slower), frame(1, faster)));
        RtuMaster master = master(link);
        assertThrows(BusTimeoutException.class, () -> master.call(1, slower, ONCE));
        assertArrayEquals(faster, master.call(1, faster, ONCE), "the confirmation of 400, not the late one of -400");
        assertEquals(1, master.statistics().staleReplies());
        assertEquals(List.of(1), strays.stream().map(RtuFrame::address).toList(), "the late one was heard");
        assertEquals(2, link.written().size(), "the stale confirmation did not cost a retry");
    }

    @Test
    void aLateConfirmationOfAnEarlierAttemptIsNoProofOfAnEchoingAdapter() {
        // a busy machine: the first write's confirmation comes only as its retry is answered, so two copies of the
        // request arrive together, as from an adapter that echoes; taken as one, every later write would lose its
        // confirmation as "the echo" and time out
        byte[] write = Pdus.writeSingleRegister(1, 400);
        AtomicInteger writes = new AtomicInteger();
        ScriptedBusLink link = new ScriptedBusLink(request -> switch (writes.getAndIncrement()) {
            case 0 -> List.of();
            case 1 -> List.of(frame(1, write), frame(1, write));
            default -> List.of(frame(1, request.length == 8 ? java.util.Arrays.copyOfRange(request, 1, 6)
                    : BUMPERS_REPLY));
        });
        RtuMaster master = master(link);
        assertArrayEquals(write, master.call(1, write, POLICY));
        assertFalse(master.echoDetected(), "no echo: the second copy was the first attempt's late reply");
        byte[] next = Pdus.writeSingleRegister(2, 0);
        assertArrayEquals(next, master.call(1, next, POLICY), "the next write is confirmed by its one reply");
        assertEquals(3, link.written().size(), "without a retry");
    }

    @Test
    void aStaleWriteConfirmationAloneIsNoConfirmation() {
        byte[] first = Pdus.writeSingleRegister(1, 100);
        byte[] second = Pdus.writeSingleRegister(1, 200);
        AtomicInteger writes = new AtomicInteger();
        ScriptedBusLink link = new ScriptedBusLink(request -> writes.getAndIncrement() == 0 ? List.of()
                : List.of(frame(1, first)));
        RtuMaster master = master(link);
        assertThrows(BusTimeoutException.class, () -> master.call(1, first, ONCE));
        assertThrows(BusTimeoutException.class, () -> master.call(1, second, ONCE));
        assertEquals(1, master.statistics().staleReplies());
    }

    @Test
    void anAddressThatDidNotAnswerIsAskedAgainOnlyAfterTheLateReplyWindowOthersAtOnce() {
        List<Long> writtenAt = new ArrayList<>();
        AtomicInteger toSeven = new AtomicInteger();
        ScriptedBusLink link = new ScriptedBusLink(request -> {
            writtenAt.add(System.nanoTime());
            boolean silent = request[0] == 7 && toSeven.getAndIncrement() == 0;
            return silent ? List.of() : List.of(frame(request[0], BUMPERS_REPLY));
        });
        // a 500 ms reply timeout, so a late-reply window of 4 x 500 ms = 2 s: far longer than any delay a busy
        // machine adds, so "at once" and "after the window" stay apart however loaded the machine is
        RtuMaster master = new RtuMaster(link, RtuTiming.of(115_200, 86_806), BusTiming.defaults()
                .withFrameGap(Duration.ZERO).withResponseTimeout(Duration.ofMillis(500)), address -> "address " + address);
        master.onStrayFrame(strays::add);
        link.open();
        assertThrows(BusTimeoutException.class, () -> master.call(7, READ_BUMPERS, ONCE));
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, ONCE));
        assertArrayEquals(BUMPERS_REPLY, master.call(7, READ_BUMPERS, ONCE));
        long toOther = (writtenAt.get(1) - writtenAt.get(0)) / 1_000_000;
        long again = (writtenAt.get(2) - writtenAt.get(0)) / 1_000_000;
        assertTrue(toOther < 1_000, "another address is asked at once, after " + toOther + " ms");
        assertTrue(again >= 1_999, "address 7 is asked again after the 2 s window, not after " + again + " ms");
        assertEquals(0, master.statistics().staleReplies());
    }

    @Test
    void aLateReplyHeardAsAStrayFrameIsNoLongerOwed() {
        // how exploration works: a probe times out, the late reply arrives while the next address is asked, and
        // the module is asked again at once
        List<Long> writtenAt = new ArrayList<>();
        AtomicInteger toSeven = new AtomicInteger();
        ScriptedBusLink link = new ScriptedBusLink(request -> {
            writtenAt.add(System.nanoTime());
            if (request[0] == 7) {
                return toSeven.getAndIncrement() == 0 ? List.of() : List.of(frame(7, BUMPERS_REPLY));
            }
            return List.of(frame(7, HexFormat.of().parseHex("020101")), frame(request[0], BUMPERS_REPLY));
        });
        // a late-reply window of 4 x 5 s: waiting it out would show as 20 s, far beyond any load
        RtuMaster master = new RtuMaster(link, RtuTiming.of(115_200, 86_806), BusTiming.defaults()
                .withFrameGap(Duration.ZERO).withResponseTimeout(Duration.ofSeconds(5)), address -> "address " + address);
        master.onStrayFrame(strays::add);
        link.open();
        RtuMaster.CallPolicy scan = new RtuMaster.CallPolicy(Duration.ofMillis(100), 3, false);
        assertThrows(BusTimeoutException.class, () -> master.call(7, READ_BUMPERS, scan));
        assertArrayEquals(BUMPERS_REPLY, master.call(8, READ_BUMPERS, scan));
        assertEquals(List.of(7), strays.stream().map(RtuFrame::address).toList());
        assertArrayEquals(BUMPERS_REPLY, master.call(7, READ_BUMPERS, POLICY));
        long again = (writtenAt.get(2) - writtenAt.get(0)) / 1_000_000;
        assertTrue(again < 10_000, "no wait for a reply already heard: asked again after " + again + " ms");
        assertEquals(0, master.statistics().staleReplies());
    }

    @Test
    void aModuleAnsweringUnderAnotherAddressIsNamedNotLeftAsAPhantom() {
        ScriptedBusLink link = new ScriptedBusLink(request -> request[0] == 5 ? List.of(frame(6, BUMPERS_REPLY))
                : List.of());
        RtuMaster master = master(link);
        BusProtocolException e = assertThrows(BusProtocolException.class, () -> master.call(5, READ_BUMPERS, POLICY));
        assertEquals(5, e.address());
        assertTrue(e.getMessage().contains("came from address 6"), e.getMessage());
        assertTrue(e.getMessage().contains("listens at address 5 but answers as address 6"), e.getMessage());
        assertEquals(List.of(), strays, "address 6 is not reported as a module that answered late");
    }

    @Test
    void aMisaddressedAnswerAlsoNamesTheAddressItCameFromAsDisturbed() {
        // the frame may be a module at 5 set to 6, or 6's late reply after its debt was paid: exploration asks 6 once
        // more (silence there means nobody), so neither a phantom nor a lost module results
        ScriptedBusLink link = new ScriptedBusLink(request -> request[0] == 5 ? List.of(frame(6, BUMPERS_REPLY))
                : List.of());
        RtuMaster master = master(link);
        List<String> disturbed = new ArrayList<>();
        master.onDisturbance((address, heard) -> disturbed.add(address + (heard ? " heard" : " disturbed")));
        assertThrows(BusProtocolException.class, () -> master.call(5, READ_BUMPERS, POLICY));
        assertTrue(disturbed.contains("6 disturbed"), disturbed.toString());
        assertEquals(List.of(), strays);
    }

    @Test
    void aLateIdentificationReplyRightBeforeAnotherReplyIsHeardNotMergedIntoNoise() {
        // at a mismatched baud rate a probe's reply comes while the module found before it is asked its status, with
        // no silence between the two replies: measured as a reply to the status request it was one broken piece
        byte[] identification = frame(9, HexFormat.of().parseHex("2b0e01010000010003414243"));
        byte[] status = frame(3, HexFormat.of().parseHex("110207ff"));
        byte[] both = new byte[identification.length + status.length];
        System.arraycopy(identification, 0, both, 0, identification.length);
        System.arraycopy(status, 0, both, identification.length, status.length);
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(both));
        RtuMaster master = master(link);
        assertArrayEquals(HexFormat.of().parseHex("110207ff"), master.call(3, Pdus.reportServerId(), POLICY));
        assertEquals(List.of(9), strays.stream().map(RtuFrame::address).toList());
        assertEquals(0, master.statistics().crcErrors());
        assertEquals(1, master.statistics().transactions());
    }

    @Test
    void aReplyCutAfterItsAddressByteLeavesThatAddressDisturbed() {
        // a stall right after the first byte: one byte is no frame, but it names who started to answer
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of());
        RtuMaster master = master(link);
        List<Integer> disturbed = new ArrayList<>();
        master.onDisturbance((address, heard) -> disturbed.add(address));
        RtuMaster.CallPolicy scan = new RtuMaster.CallPolicy(Duration.ofMillis(5), 3, false);
        link.respondWith(request -> request[0] == 2 ? List.of(new byte[] {9}) : List.of());
        assertThrows(BusException.class, () -> master.call(2, READ_BUMPERS, scan));
        assertTrue(disturbed.contains(9), "the address byte of the cut piece: " + disturbed);
    }

    @Test
    void aLateReplyFromAnotherAddressBeforeOursIsStillAStray() {
        // the frame from 9 owes nothing (its request is long forgotten), but address 2 answers: 9 was just late
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(frame(9, BUMPERS_REPLY),
                frame(request[0], BUMPERS_REPLY)));
        RtuMaster master = master(link);
        assertArrayEquals(BUMPERS_REPLY, master.call(2, READ_BUMPERS, POLICY));
        assertEquals(List.of(9), strays.stream().map(RtuFrame::address).toList());
    }

    @Test
    void anEchoOfSeveralWordsComesBackWhole() throws Exception {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(request));
        try (RS485Bus bus = new RS485Bus(link, SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withFrameGap(Duration.ZERO))) {
            bus.echo(3, 0x0102, 0x0304, 0x0506, 0x0708);
            assertEquals(Pdus.echo(0x0102, 0x0304, 0x0506, 0x0708).length + 3, link.written().get(0).length);
        }
    }

    @Test
    void aSplitIdentificationIsFollowedToItsEnd() throws Exception {
        HexFormat hex = HexFormat.of();
        ScriptedBusLink link = new ScriptedBusLink(request -> {
            int from = request[4] & 0xFF; // address 2B 0E 01 objectId
            String pdu = switch (from) {
                case 0 -> "2B0E0101FF0101000441434D45"; // VendorName "ACME"; more follows, at object 1
                case 1 -> "2B0E0101FF0201010731354236334232"; // ProductCode "15B63B2"; more follows, at 2
                default -> "2B0E01010000010203312E30"; // MajorMinorRevision "1.0"; done
            };
            return List.of(frame(request[0], hex.parseHex(pdu)));
        });
        try (RS485Bus bus = new RS485Bus(link, SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withFrameGap(Duration.ZERO))) {
            robotworld.bus.modbus.DeviceIdentification id = bus.identify(4);
            assertEquals("ACME", id.vendorName());
            assertEquals("15B63B2", id.productCode());
            assertEquals("1.0", id.revision());
            assertEquals(3, link.written().size());
            assertEquals(List.of(0, 1, 2), link.written().stream().map(w -> w[4] & 0xFF).toList());
        }
    }

    @Test
    void aSplitIdentificationThatDoesNotProgressIsAProtocolError() throws Exception {
        ScriptedBusLink link = new ScriptedBusLink(request -> List.of(frame(request[0],
                HexFormat.of().parseHex("2B0E0101FF0001000141"))));
        try (RS485Bus bus = new RS485Bus(link, SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withFrameGap(Duration.ZERO))) {
            BusProtocolException e = assertThrows(BusProtocolException.class, () -> bus.identify(4));
            assertTrue(e.getMessage().contains("does not progress"), e.getMessage());
        }
    }
}
