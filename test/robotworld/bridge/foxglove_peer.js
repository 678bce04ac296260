// The reference Foxglove WebSocket client (npm @foxglove/ws-protocol, over the npm ws package) as a test peer.
//
//   node foxglove_peer.js URL SECONDS TOPIC...
//
// Connects with subprotocol foxglove.websocket.v1, prints one JSON line per event to stdout:
//   {"event":"serverInfo", ...}  {"event":"advertise","channels":[...]}  {"event":"status", ...}
//   {"event":"message","topic":T,"schemaName":S,"receiveTime":"ns","data":<the JSON message>}
// subscribes to every advertised channel whose topic is one of TOPIC (all when none is given), and ends when its
// standard input closes (or after SECONDS at the latest), or with exit code 2 on a connection error.
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const WebSocket = require("ws");

const [url, seconds, ...topics] = process.argv.slice(2);
const out = (event) => process.stdout.write(JSON.stringify(event) + "\n");
const client = new FoxgloveClient({ ws: new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
const channels = new Map();
const bySubscription = new Map();
const decoder = new TextDecoder();

client.on("open", () => out({ event: "open" }));
client.on("error", (error) => {
  out({ event: "error", message: String(error && error.message ? error.message : error) });
  process.exit(2);
});
client.on("close", (event) => out({ event: "close", code: event && event.code }));
client.on("serverInfo", (info) => out({ event: "serverInfo", ...info }));
client.on("status", (status) => out({ event: "status", ...status }));
client.on("advertise", (advertised) => {
  out({ event: "advertise", channels: advertised.map((c) => ({ id: c.id, topic: c.topic, encoding: c.encoding,
    schemaName: c.schemaName, schemaEncoding: c.schemaEncoding, schemaLength: c.schema.length })) });
  for (const channel of advertised) {
    channels.set(channel.id, channel);
    if (topics.length === 0 || topics.includes(channel.topic)) {
      bySubscription.set(client.subscribe(channel.id), channel);
    }
  }
});
client.on("message", ({ subscriptionId, timestamp, data }) => {
  const channel = bySubscription.get(subscriptionId);
  const text = decoder.decode(data);
  out({ event: "message", topic: channel ? channel.topic : null, schemaName: channel ? channel.schemaName : null,
    receiveTime: String(timestamp), data: JSON.parse(text) });
});
const end = () => {
  client.close();
  process.exit(0);
};
process.stdin.on("end", end);
process.stdin.on("close", end);
process.stdin.resume();
setTimeout(end, Number(seconds) * 1000);
