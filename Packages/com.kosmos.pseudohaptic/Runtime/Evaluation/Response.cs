namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// One answer as given: participant, questionnaire id, item number, the point chosen on the scale
    /// (before reverse coding). One row of the responses CSV, participant,questionnaire,item,response.
    /// </summary>
    public readonly struct Response
    {
        public string Participant { get; }
        public string QuestionnaireId { get; }
        public int Item { get; }
        public int Value { get; }

        public Response(string participant, string questionnaireId, int item, int value)
        {
            Participant = participant;
            QuestionnaireId = questionnaireId;
            Item = item;
            Value = value;
        }

        public override string ToString() => Participant + "," + QuestionnaireId + "," + Item + "," + Value;
    }
}
